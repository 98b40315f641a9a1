// Löw et al.'s claim (docs/study.md, "Does BRDF-space error predict image error?"): for each BRDF metric
// (E1, E2) and image figure (r*, ꟻLIP), their rank correlations pooled over every (material, model) pair and
// within each material across its fits, the share of materials whose metric-best fit is the image-best, and
// E2's ρ minus E1's as a paired interval both ways.
#pragma once

#include "renderer/study/study_analysis.h"
#include "renderer/study/study_data.h"

#include <string>

namespace glossy::study {

// results.json's "brdfVsImage"; `differences` gets "e2MinusE1", `headline` the summary's lines on the claim.
Json brdfVsImage(const Study& s, const AnalysisOptions& o, Json& differences, std::string& headline);

}  // namespace glossy::study
