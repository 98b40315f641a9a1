// glossy's figures against people's (docs/study.md, "Against people"), across materials: for each of the
// fits Lavoué et al. 2021 judged that the study has, each figure's (r*, ꟻLIP, E1, E2) Spearman ρ and
// Kendall τ-b with the perceived distance over the materials that have both, with intervals, and which
// figure agrees best. The within-material question, which approximation looks closest, is study_people.h's.
#pragma once

#include "renderer/study/perceptual.h"
#include "renderer/study/study_analysis.h"
#include "renderer/study/study_data.h"
#include "renderer/study/study_figures.h"

#include <string>
#include <vector>

namespace glossy::study {

// results.json's "againstPeople" (without its "withinMaterial"); `data` null: no perceptual data, said so.
// `headline` gets the summary's lines, `series` each fit's points for the perceptual figure.
Json againstPeople(const Study& s, const AnalysisOptions& o, const PerceptualData* data, std::string& headline,
                   std::vector<PerceptualSeries>& series);

}  // namespace glossy::study
