#include "renderer/study/study_summary.h"

#include "materials/core/text.h"
#include "renderer/study/study_intervals.h"
#include "renderer/study/study_methods.h"
#include "renderer/study/study_tables.h"

namespace glossy::study {

// The summary's text: counts, verdicts, each model's line, the rank tests, lighting, the claims about
// BRDF-space and image error, a small sample's caveat, and the comparison with people.
std::string summaryText(const Study& s, const RankTests& t, const VerdictCounts& v, const Json& results,
                        const std::string& lightingHeadline, const std::string& claimHeadline, const std::string& peopleHeadline) {
  std::string summary = "Study: " + std::to_string(s.materials.size()) + " materials, " + std::to_string(s.sheets.size()) +
                        " sheets, " + std::to_string(s.models.size()) + " models; " + std::to_string(s.used.size()) + " rows used";
  if (s.skipped) summary += ", " + std::to_string(s.skipped) + " without rRMSE skipped";
  summary += ".\n";
  summary += "Verdicts: " + std::to_string(v.decided) + " of " + std::to_string(s.sheets.size()) + " sheets name one closest model, " +
             std::to_string(v.tied) + " a tie, " + std::to_string(v.none) +
             " none (intervals that do not part the models, or a warning that they may be too narrow)";
  if (v.clamped > 0) summary += "; " + std::to_string(v.clamped) + " r* clamped to 0 (the model within the render noise), ranked as 0";
  summary += ".\n";
  const Json& noise = results["renderNoise"];
  if (!noise["medianHalfWidth"].is_null())
    summary += formatted("Render noise: the sheets' r* intervals have a median half-width of %.2g (90 %% at most %.2g); on %d of %d rows "
                         "it is as large as r* itself. Where it is large, r* reads low and its correlations weaker (docs/study.md, "
                         "\"Render noise\").\n",
                         noise["medianHalfWidth"].get<double>(), noise["p90HalfWidth"].get<double>(),
                         noise["rowsHalfWidthAtLeastRrmse"].get<int>(), noise["rows"].get<int>());
  for (const Json& m : results["models"])
    summary += "  " + m["label"].get<std::string>() + ": closest on " + std::to_string(m["closest"].get<int>()) + " of " +
               std::to_string(m["sheets"].get<int>()) + " sheets, tied on " + std::to_string(m["tied"].get<int>()) +
               "; mean rank " + (m["meanRank"].is_null() ? std::string("—") : formatted("%.2f", m["meanRank"].get<double>())) +
               "; mean rRMSE " + intervalCell(m["meanRrmse"]) +
               (m["rrmseClamped"].get<int>() > 0 ? "; r* clamped to 0 on " + std::to_string(m["rrmseClamped"].get<int>()) : "") + "\n";
  if (t.friedmanTested) {
    summary += formatted("Friedman χ² = %.3f (df %d), p = %.3g", t.friedman->chiSquare, t.friedman->treatments - 1, t.friedman->pChiSquare);
    if (t.friedman->pF) summary += formatted("; Iman–Davenport F p = %.3g", *t.friedman->pF);
    summary += " over " + std::to_string(t.complete.size()) + " materials.\n";
    const std::string groups = joined(results["wilcoxon"]["cliques"], "; ", [](const Json& c) { return c.dump(); });
    summary += "Not significantly different (Holm–Wilcoxon, α = 0.05): " + (groups.empty() ? std::string("none") : groups) + ".\n";
  } else {
    summary += "Friedman test: none (" + t.friedmanReason + ").\n";
  }
  summary += lightingHeadline;
  summary += claimHeadline + "\n";
  if (s.materials.size() < kIntervalMinMaterials)
    summary += "A small sample: no interval (" + tooFewForInterval(s.materials.size()) + ")" +
               (s.materials.size() < kTestMinMaterials ? "; no test (" + tooFewForTest(s.materials.size()) + ")" : std::string()) +
               " — docs/study.md, \"Small samples\", says why.\n";
  if (!peopleHeadline.empty()) summary += peopleHeadline + "\n";
  return summary;
}

// summary.md: the summary, the lighting table, where every other output is, the figures' captions and the
// methods.
std::string summaryMarkdown(const std::string& summary, const std::string& lightingMarkdown, const std::vector<StudyFigure>& figures,
                            const Json& results, bool peopleTex, const AnalysisOptions& options) {
  const bool studyFile = options.provenance && !options.provenance->studyText.empty();
  std::string md = "# Study summary\n\n```\n" + summary + "```\n\n" + lightingMarkdown +
                   "\nEvery statistic with its interval: `results.json`; "
                   "the rows: `rows.csv`, `rows.json`; per-model tables: `models.tex`; per-lighting table: `lighting.tex`; "
                   "methods: `methods.tex`" + std::string(peopleTex ? "; against people: `people.tex`" : "") +
                   std::string(studyFile ? "; the study file: `study.toml`" : "") + "; figures: ";
  for (std::size_t i = 0; i < figures.size(); ++i) md += (i ? ", " : "") + std::string("`") + figures[i].name + ".svg`";
  md += ".\n\n## Figures\n\n";
  for (const StudyFigure& f : figures) {
    std::string text;  // "r*" is not Markdown's emphasis
    for (char c : f.caption) text += c == '*' ? std::string("\\*") : std::string(1, c);
    md += "- `" + f.name + ".svg`: " + text + "\n";
  }
  if (!options.perceptualDir.empty())
    md += "\nPerceived distances: Lavoué, Bonneel, Farrugia, Soler, \"Perceptual quality of BRDF approximations: dataset and "
          "metrics\", Computer Graphics Forum 40(2), 2021.\n";
  md += "\n## Methods\n\n" + methodsMarkdown(results);
  return md;
}

}  // namespace glossy::study
