// How the study states an interval or a test (docs/study.md, "Small samples"): every interval of the
// analysis is a percentile bootstrap over materials with its own seeded stream, and is absent — with the
// reason, never a degenerate [x, x] — when there are too few materials for it to mean what it says, or when
// every resample gives the same value; a test is absent below its own number of materials.
#pragma once

#include "renderer/study/study_statistics.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace glossy::study {

// Below this many materials a 95 % percentile bootstrap interval covers far less than 95 %: simulated,
// it covers 82 % at 5 materials and 90 % at 10 for normal data (75 % and 84 % for log-normal data as
// skewed as r*), so an interval needs at least 10 materials.
constexpr std::size_t kIntervalMinMaterials = 10;
// Below this many materials no test of two models can be significant at 0.05 (the sign test's and
// Wilcoxon's smallest two-sided p with 5 materials is 2/32 = 0.0625), and Friedman's χ² approximation is
// poor; a test needs at least 6.
constexpr std::size_t kTestMinMaterials = 6;

// "n/a: 1 material; intervals need ≥ 10" and "n/a: 3 materials; tests need ≥ 6".
std::string tooFewForInterval(std::size_t materials);
std::string tooFewForTest(std::size_t materials);

// A bootstrap's own seed: the study's seed mixed with the statistic's name, so that adding a statistic
// leaves the others' intervals unchanged.
std::uint64_t seedFor(std::uint64_t seed, const std::string& key);

// The statistic on `materials` units (every unit a material) and its interval (bootstrap, study_statistics.h).
// `withValue`: how many of them the statistic has a value on (a mean of per-material values left undefined
// on some), when fewer than `materials`. The estimate stays; the interval is absent, with its reason, when
// fewer than kIntervalMinMaterials materials carry it or when every resample gives the same value.
Interval materialInterval(std::size_t materials,
                          const std::function<std::optional<double>(const std::vector<std::size_t>&)>& statistic,
                          int resamples, std::uint64_t seed, std::optional<std::size_t> withValue = std::nullopt);

// An interval as results.json writes it: estimate, lo, hi, resamples, undefinedResamples, and the reason
// when something is absent.
nlohmann::ordered_json intervalJson(const Interval& interval);
// An interval as the summary writes it: "0.123 [0.101, 0.145]", "0.123 (n/a: 3 materials; intervals
// need ≥ 10)", "0.123 (no interval: REASON)", or "undefined (REASON)".
std::string intervalText(const Interval& interval, const char* format = "%.4g");

// A Friedman test as results.json writes it, overall and per lighting alike: χ², its df and p, Iman and
// Davenport's F, its df and p; or a null p with `reason` when the test is absent.
nlohmann::ordered_json friedmanJson(const std::optional<FriedmanResult>& test, const std::string& reason);

}  // namespace glossy::study
