// The study's intervals and their small-sample rules (study_intervals.h).
#include "renderer/study/study_intervals.h"

#include "materials/core/text.h"

#include <numeric>

namespace glossy::study {

namespace {

std::string materialsText(std::size_t n) { return std::to_string(n) + (n == 1 ? " material" : " materials"); }

}  // namespace

std::string tooFewForInterval(std::size_t materials) {
  return "n/a: " + materialsText(materials) + "; intervals need \xE2\x89\xA5 " + std::to_string(kIntervalMinMaterials);
}

std::string tooFewForTest(std::size_t materials) {
  return "n/a: " + materialsText(materials) + "; tests need \xE2\x89\xA5 " + std::to_string(kTestMinMaterials);
}

std::uint64_t seedFor(std::uint64_t seed, const std::string& key) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : key) h = (h ^ c) * 1099511628211ull;
  std::uint64_t z = seed + h + 0x9e3779b97f4a7c15ull;  // splitmix64's finaliser
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

Interval materialInterval(std::size_t materials,
                          const std::function<std::optional<double>(const std::vector<std::size_t>&)>& statistic,
                          int resamples, std::uint64_t seed, std::optional<std::size_t> withValue) {
  const std::size_t carried = withValue.value_or(materials);
  if (carried < kIntervalMinMaterials) {
    // The point estimate still describes the materials at hand; only the interval would overstate.
    Interval out;
    std::vector<std::size_t> all(materials);
    std::iota(all.begin(), all.end(), 0);
    out.estimate = materials > 0 ? statistic(all) : std::nullopt;
    out.reason = !out.estimate ? (materials == 0 ? "no data" : "undefined on these data") : tooFewForInterval(carried);
    return out;
  }
  Interval out = bootstrap(materials, statistic, resamples, seed);
  if (out.lo && out.hi && *out.lo == *out.hi) {
    // Every material agrees (a share of 1, a correlation of 1 on each): resampling them cannot say how far
    // another sample of materials could fall from it.
    out.reason = "no interval: every resample gives " + formatted("%.4g", *out.lo) + " (the " + materialsText(carried) +
                 " agree; the bootstrap cannot bound it)";
    out.lo.reset();
    out.hi.reset();
  }
  return out;
}

nlohmann::ordered_json intervalJson(const Interval& i) {
  nlohmann::ordered_json j;
  const auto num = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr); };
  j["estimate"] = num(i.estimate);
  j["lo"] = num(i.lo);
  j["hi"] = num(i.hi);
  j["resamples"] = i.resamples;
  j["undefinedResamples"] = i.undefined;
  if (!i.reason.empty()) j["reason"] = i.reason;
  return j;
}

std::string intervalText(const Interval& i, const char* f) {
  if (!i.estimate) return "undefined (" + i.reason + ")";
  std::string s = formatted(f, *i.estimate);
  if (i.lo && i.hi) {
    s += " [" + formatted(f, *i.lo) + ", " + formatted(f, *i.hi) + "]";
  } else if (!i.reason.empty()) {
    const bool said = i.reason.starts_with("no interval") || i.reason.starts_with("n/a");
    s += " (" + (said ? i.reason : "no interval: " + i.reason) + ")";
  }
  return s;
}

nlohmann::ordered_json friedmanJson(const std::optional<FriedmanResult>& test, const std::string& reason) {
  const auto num = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr); };
  nlohmann::ordered_json j;
  if (!test) {
    j["p"] = nullptr;
    j["reason"] = reason;
    return j;
  }
  j["chiSquare"] = test->chiSquare;
  j["df"] = test->treatments - 1;
  j["p"] = test->pChiSquare;
  j["imanDavenportF"] = num(test->imanDavenportF);
  if (!test->imanDavenportF) j["imanDavenportFReason"] = "infinite: every material ranks the models alike";
  j["fDf"] = nlohmann::ordered_json::array({test->treatments - 1, (test->treatments - 1) * (test->blocks - 1)});
  j["pF"] = num(test->pF);
  return j;
}

}  // namespace glossy::study
