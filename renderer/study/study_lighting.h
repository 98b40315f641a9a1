// Lighting as an output of a study (docs/study.md, "Lighting"): the models' ranks and tests under each
// lighting on its own, how far the lightings agree on the ranking (Kendall's W, with an interval over
// materials), and which materials' verdict changes with the lighting. Rows in; results.json's "lighting",
// the summary's section and lighting.tex out.
#pragma once

#include "renderer/study/study_row.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace glossy::study {

struct LightingAnalysis {
  nlohmann::ordered_json json;  // results.json's "lighting"
  std::string headline;         // a paragraph of the printed summary
  std::string markdown;         // summary.md's section "Lighting", with a table per lighting
  std::string tex;              // lighting.tex: a table float of plain LaTeX, caption and label
};

// `rows`: the rows the statistics use (each with an rrmse; at most one per model and sheet). `models`: the
// models' labels in the order the tables list them (the study's rank order). Each material's figure under
// a lighting is the mean over its scenes; intervals and tests follow study_intervals.h. Deterministic for
// the rows (in any order) and `seed`.
LightingAnalysis analyseLighting(const std::vector<const StudyRow*>& rows, const std::vector<std::string>& models,
                                 int resamples, std::uint64_t seed);

}  // namespace glossy::study
