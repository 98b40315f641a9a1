// The study's verdicts (docs/study.md, "The statistics"): per material, each sheet's (the closest model, a
// tie or none, and its models in order of r*), the model of the best mean rank across the material's
// lightings with how many sheets name another, and Kendall's W of the sheets' ranks; over the study, how
// many sheets were decided and how noisy their r* are.
#pragma once

#include "renderer/study/study_data.h"

namespace glossy::study {

// results.json's "materials": a row per material.
Json perMaterial(const Study& s);

// The sheets' verdicts: how many name one model, a tie, or none (the intervals do not part the models, or
// the sheet warns that they may be too narrow); and the r* that are 0 by clamping.
struct VerdictCounts {
  int decided = 0, tied = 0, none = 0, clamped = 0;
};

VerdictCounts verdictCounts(const Study& s);
// results.json's "counts".
Json countsJson(const Study& s, const VerdictCounts& v);
// results.json's "renderNoise": the sheets' r* intervals' half-widths.
Json renderNoiseJson(const Study& s);

}  // namespace glossy::study
