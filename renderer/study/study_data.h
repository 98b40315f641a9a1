// A study's rows arranged for its statistics (study_analysis.h): per sheet, and per material and model the
// figures averaged over the material's sheets, which every analysis reads. The unit of the study is the
// material: a material's lightings are not independent evidence about the models, so tests, intervals and
// correlations treat materials as the draws and bootstraps resample them with their sheets.
#pragma once

#include "renderer/study/study_row.h"
#include "renderer/study/study_statistics.h"

#include <nlohmann/json.hpp>

#include <compare>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace glossy::study {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

inline Json num(const Opt& v) { return v ? Json(*v) : Json(nullptr); }

// A sheet of the study: its material under one lighting in one scene.
struct SheetKey {
  std::string material, lighting, scene;
  auto operator<=>(const SheetKey&) const = default;
};

// The rows as the analyses read them.
struct Study {
  std::vector<StudyRow> all;   // every row, canonical order
  std::vector<const StudyRow*> used;
  int skipped = 0;
  std::vector<std::string> models;     // labels, sorted
  std::vector<std::string> materials;  // sorted
  std::map<std::string, std::string> database, materialClass;
  std::map<SheetKey, std::map<std::string, const StudyRow*>> sheets;
  // Per material and model: the figure averaged over the material's sheets.
  std::vector<std::vector<Opt>> rrmse, flip, e1, e2;
  // Per model: its first row's fit and source (for its colour), and every fit and source its rows carry
  // (a model's label covers the published fit on one database and glossy's on another).
  std::vector<std::string> fitOf, sourceOf;
  std::vector<std::set<std::string>> fitsOf, sourcesOf;
};

// A bootstrap's statistic: the mean of the defined values among the materials drawn.
inline auto meanOfDrawn(const std::vector<Opt>& values) {
  return [&values](const std::vector<std::size_t>& drawn) {
    std::vector<double> v;
    for (std::size_t i : drawn)
      if (values[i]) v.push_back(*values[i]);
    return meanOf(v);
  };
}

// The rank correlations the study reports, by their name in results.json.
using Corr = std::optional<double> (*)(const std::vector<double>&, const std::vector<double>&);
inline const std::pair<const char*, Corr> kCorrelations[] = {{"spearman", spearman}, {"kendallTauB", kendallTauB}};

// Paired values a correlation is computed on.
struct Pair {
  std::vector<double> x, y;
};

// Each rank correlation of kCorrelations over the pairs `pairsOf` gives for drawn materials (indices among
// `materials`), with its bootstrap interval over materials seeded by "KEY/NAME", added to `out` under its
// name ("spearman", "kendallTauB"); returns the Spearman interval.
Interval addCorrelations(Json& out, std::size_t materials, const std::function<Pair(const std::vector<std::size_t>&)>& pairsOf,
                         int resamples, std::uint64_t seed, const std::string& key);

// The rows in a canonical order, each sheet's rows by model label, and the per-material means. Throws
// InputError for a row without material or label, a figure that is not finite, or a model twice on a sheet.
Study readRows(std::span<const StudyRow> rows);

}  // namespace glossy::study
