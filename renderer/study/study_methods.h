// A study's methods paragraph, generated from its results.json (study_provenance.h, study_analysis.h) so
// that a paper can quote it as it stands: what was rendered (materials and databases, whether the measured
// panels are tables or NBRDF reconstructions, lightings, scenes, panel size, samples, depth, seed), which
// fits (each model's, by source), and what the statistics are (ranks, Friedman and Iman–Davenport,
// Holm-corrected Wilcoxon, the "closer than" shares, percentile bootstrap intervals with their resamples
// and seed). The same sentences in Markdown (summary.md) and LaTeX (methods.tex).
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace glossy::study {

std::string methodsMarkdown(const nlohmann::ordered_json& results);
// A LaTeX fragment (a paragraph; ASCII, no package beyond LaTeX's own) to \input into a paper.
std::string methodsTex(const nlohmann::ordered_json& results);

}  // namespace glossy::study
