// The study's summary (docs/study.md, "Outputs"): the printed text — counts, verdicts, each model's line,
// the rank tests, lighting, the claim about BRDF-space and image error, a small sample's caveat and the
// comparison with people — and summary.md, which adds the tables, where every other output is, the
// figures' captions and the methods.
#pragma once

#include "renderer/study/study_analysis.h"
#include "renderer/study/study_data.h"
#include "renderer/study/study_figures.h"
#include "renderer/study/study_ranks.h"
#include "renderer/study/study_verdicts.h"

#include <string>
#include <vector>

namespace glossy::study {

std::string summaryText(const Study& s, const RankTests& t, const VerdictCounts& v, const Json& results,
                        const std::string& lightingHeadline, const std::string& claimHeadline, const std::string& peopleHeadline);

std::string summaryMarkdown(const std::string& summary, const std::string& lightingMarkdown, const std::vector<StudyFigure>& figures,
                            const Json& results, bool peopleTex, const AnalysisOptions& options);

}  // namespace glossy::study
