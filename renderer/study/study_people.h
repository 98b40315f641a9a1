// Which approximation looks closest, to people and to glossy, within a material (docs/study.md, "Against
// people"): the question glossy exists for, asked of Lavoué et al. 2021's perceived distances
// (perceptual.h) for the approximations the dataset and glossy share — Löw et al.'s ABC (one of its two
// published E2 fits: each in turn, since which one the dataset rendered is not stated), Ngan et al. 2005's
// Ward, Blinn-Phong and Lafortune, and Bagher et al. 2012's SGD. For each glossy figure (r*, ꟻLIP, ΔE_ITP,
// SSIM as 1 − SSIM, E1, E2), over the materials that have the figure and a perceived distance for every
// approximation:
//   - pooled Spearman ρ over every (material, approximation) pair (chance: 0);
//   - the mean over materials of the within-material Kendall τ-b of figure and distance (chance: 0);
//   - the share of materials where the figure's closest approximation is people's closest, a tie shared
//     (|G ∩ P| / (|G| |P|) for the tied sets G and P; chance: 1 / the number of approximations);
// each with a bootstrap interval over materials (study_intervals.h): overall, each figure the mean over the
// material's sheets, and under each lighting alone (the mean over its scenes).
#pragma once

#include "renderer/study/perceptual.h"
#include "renderer/study/study_row.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace glossy::study {

struct PeopleAnalysis {
  nlohmann::ordered_json json;  // results.json's againstPeople.withinMaterial
  std::string headline;         // lines of the printed summary
  std::string markdown;         // summary.md's section "Against people": per ABC variant, overall and per lighting
  std::string tex;              // people.tex: the same as LaTeX tables (no package needed); "" without a material to compare
};

// `rows`: the rows the statistics use. Deterministic for the rows (in any order) and `seed`.
PeopleAnalysis closestToPeople(const std::vector<const StudyRow*>& rows, const PerceptualData& data, int resamples,
                               std::uint64_t seed);

}  // namespace glossy::study
