// The study's per-model results as LaTeX a paper can \input as they stand (docs/study.md, "The files"):
// tables (booktabs) with a caption and a label, the models in order of mean rank, each with its group —
// letters shared by models the Holm-corrected Wilcoxon tests do not separate — and the effect sizes, the
// "closer than" shares of materials with their intervals. Generated from results.json.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace glossy::study {

// The models' labels in rank order (mean rank, then label; models without a mean rank last, by label), as
// the critical-difference diagram orders them.
std::vector<std::string> modelsByRank(const nlohmann::ordered_json& results);

// Per model (in `order`), its group letters: "a", "ab", … Models sharing a letter are in one of results.json's
// wilcoxon.cliques; a model in none has a letter of its own.
std::vector<std::string> groupLetters(const nlohmann::ordered_json& results, const std::vector<std::string>& order);

// models.tex: the per-model table (label tab:glossy-study-models) and the pairwise "closer than" table
// (tab:glossy-study-closer). Needs \usepackage{booktabs}.
std::string modelsTex(const nlohmann::ordered_json& results);

}  // namespace glossy::study
