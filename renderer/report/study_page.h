// The report of a study (docs/study.md, docs/report.md): its top page — the analysis's summary, its figures
// and files, and a table of every row (material × lighting × scene × model) linking to the page of the row's
// sheet, which sits in a sheets site of its own per scene and lighting (study_layout below).
#pragma once

#include "renderer/study/study_plan.h"
#include "renderer/study/study_row.h"

#include <map>
#include <string>
#include <vector>

namespace glossy::report {

namespace study_layout {
// The sheets site of one scene and lighting, relative to the study site's top, with a trailing '/'.
inline std::string sheetsSite(const std::string& scene, const std::string& lighting) {
  return "sheets/" + scene + "/" + lighting + "/";
}
// The analysis's files, copied as they are.
inline std::string analysisFile(const std::string& relative) { return "analysis/" + relative; }
}  // namespace study_layout

// The analysis's outputs as the page shows them: relative paths under OUT/analysis.
struct StudyFiles {
  std::string summary;              // the text of its summary file, "" when it has none
  std::vector<std::string> figures;  // shown as pictures (SVG, else PNG of the same stem)
  std::vector<std::string> others;   // linked (CSV, JSON, LaTeX, the figures' other formats)
  std::map<std::string, std::string> captions;  // by figure stem, as results.json gives them
};

std::string studyPage(const study::StudyPlan& plan, const std::vector<study::StudyRow>& rows, const StudyFiles& files);

}  // namespace glossy::report
