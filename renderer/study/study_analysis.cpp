// The study's statistics (docs/study.md, "The statistics"), in the order results.json holds them: the rows
// arranged by material and model (study_data.h), the verdicts (study_verdicts.h), the ranks and their tests
// (study_ranks.h), lighting (study_lighting.h), Löw et al.'s claim (study_claim.h), people's judgments
// (study_people_correlations.h, study_people.h), then the summary, the figures and the files.
#include "renderer/study/study_analysis.h"

#include "materials/core/input_error.h"
#include "renderer/plot/svg_to_png.h"
#include "renderer/sheet/comparison_grid.h"
#include "renderer/study/perceptual.h"
#include "renderer/study/study_claim.h"
#include "renderer/study/study_data.h"
#include "renderer/study/study_figures.h"
#include "renderer/study/study_latex.h"
#include "renderer/study/study_lighting.h"
#include "renderer/study/study_methods.h"
#include "renderer/study/study_people.h"
#include "renderer/study/study_people_correlations.h"
#include "renderer/study/study_provenance.h"
#include "renderer/study/study_ranks.h"
#include "renderer/study/study_summary.h"
#include "renderer/study/study_tables.h"
#include "renderer/study/study_verdicts.h"
#include "renderer/util/atomic_file.h"

#include <algorithm>
#include <optional>
#include <set>

namespace glossy::study {

namespace {

// Each model's colour in the figures and its legend's note: its fit's colour on the sheets
// (comparison_grid.h), or, for a fit the grid lacks or a second model of one fit (the published and
// glossy's), the grid's first colour no other model has.
std::vector<ModelStyle> modelStyles(const Study& s) {
  std::vector<ModelStyle> out;
  std::set<std::string> used;
  for (std::size_t k = 0; k < s.models.size(); ++k) {
    ModelStyle m{s.models[k], {}, ""};
    const std::string fit = s.fitOf[k].substr(0, s.fitOf[k].find(':', s.fitOf[k].find(':') + 1));
    const bool known = std::any_of(gridFits().begin(), gridFits().end(), [&](const GridFit& g) { return g.fit == fit; });
    m.style.colour = std::string(fitColour(fit));
    if (!known || used.count(m.style.colour))
      for (const GridFit& g : gridFits())
        if (!used.count(std::string(g.colour))) {
          m.style.colour = std::string(g.colour);
          break;
        }
    // Solid lines throughout (a dashed curve of many materials reads as gaps); whose fit it is, the legend says.
    if (s.sourcesOf[k].size() > 1) m.note = "published and glossy's fits";
    else if (s.sourcesOf[k].count("glossy")) m.note = "glossy's fit";
    used.insert(m.style.colour);
    out.push_back(m);
  }
  return out;
}

// The analysis's figures, in the order summary.md and the report list them.
std::vector<StudyFigure> studyFigures(const Study& s, const RankTests& t, const AnalysisOptions& options,
                                      const std::vector<PerceptualSeries>& series) {
  MaterialTable table{s.materials, modelStyles(s), s.rrmse, s.flip, s.e1, s.e2};
  std::vector<StudyFigure> figures = {
      {"error_curves", errorCurvesSvg(table, options.referenceModel), errorCurvesCaption(table, options.referenceModel)},
      {"heat_map", heatMapSvg(table), heatMapCaption()},
  };
  std::vector<CdModel> cd;
  if (t.friedman)
    for (std::size_t k : t.rankOrder) cd.push_back({s.models[k], t.friedman->meanRanks[k]});
  std::string test = t.methods.empty() ? std::string("no Wilcoxon test") : *t.methods.begin();
  if (t.methods.size() > 1) test = "exact or normal approximation";
  figures.push_back({"critical_difference", criticalDifferenceSvg(cd, t.cliques, int(t.complete.size()), test),
                     criticalDifferenceCaption(int(t.complete.size()), test)});
  figures.push_back({"brdf_vs_image", brdfVsImageSvg(table), brdfVsImageCaption()});
  if (!options.perceptualDir.empty())
    figures.push_back({"perceptual", perceptualSvg(series, {"rRMSE r*", "ꟻLIP", "E1", "E2"}), perceptualCaption()});
  return figures;
}

// The analysis's files in `folder`, in this order: the rows, each figure (and its PNG when rsvg-convert is
// installed), results.json with the figures' list, the LaTeX (people.tex with perceptual data), the study
// file and summary.md.
AnalysisResult writeAnalysis(const std::filesystem::path& folder, const Study& s, const std::string& summary, Json& results,
                             const std::vector<StudyFigure>& figures, const LightingAnalysis& lighting, const PeopleAnalysis& people,
                             const AnalysisOptions& options) {
  AnalysisResult result;
  result.summary = summary;
  auto write = [&](const std::string& name, const std::string& contents) {
    writeFileAtomically(folder / name, contents);
    result.files.emplace_back(name);
  };
  const auto dump = [](const Json& j) { return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"; };
  write("rows.csv", rowsCsv(s.all));
  write("rows.json", dump(rowsJson(s.all)));
  Json figureList = Json::array();
  const auto rsvg = plot::findRsvgConvert();
  for (const StudyFigure& f : figures) {
    write(f.name + ".svg", f.svg);
    if (rsvg) {
      plot::svgToPng(*rsvg, folder / (f.name + ".svg"), folder / (f.name + ".png"), 1.5);
      result.files.emplace_back(f.name + ".png");
    }
    figureList.push_back({{"name", f.name}, {"svg", f.name + ".svg"}, {"png", rsvg ? Json(f.name + ".png") : Json(nullptr)}, {"caption", f.caption}});
  }
  results["figures"] = figureList;
  write("results.json", dump(results));
  write("models.tex", modelsTex(results));
  write("lighting.tex", lighting.tex);
  write("methods.tex", methodsTex(results));
  if (!people.tex.empty()) write("people.tex", people.tex);
  // The study file as it was read: the settings of these results, beside them.
  if (options.provenance && !options.provenance->studyText.empty()) write(kStudyFileCopy, options.provenance->studyText);
  write("summary.md", summaryMarkdown(summary, lighting.markdown + (people.markdown.empty() ? "" : "\n" + people.markdown), figures,
                                      results, !people.tex.empty(), options));
  return result;
}
}  // namespace

double expectedAnalysisSeconds(int resamples, std::size_t materials, std::size_t models) {
  constexpr double kSecondsPerUnit = 25.0 / (2000.0 * 100.0 * 36.0);
  return kSecondsPerUnit * double(resamples) * double(materials) * double(models) * double(models);
}

AnalysisResult analyseStudy(std::span<const StudyRow> rows, const AnalysisOptions& options, const std::filesystem::path& folder) {
  if (options.resamples < 0 || options.resamples > 1000000)
    throw InputError("study: bootstrap resamples " + std::to_string(options.resamples) + " outside 0 … 1000000");
  constexpr int kSteps = 6;
  const auto step = [&](int k, const std::string& what) {
    if (options.progress) options.progress(k, kSteps, what);
  };
  step(1, "rows, verdicts and rank tests");
  // The perceptual data are read first: a malformed table stops the analysis before anything is written.
  std::optional<PerceptualData> people;
  if (!options.perceptualDir.empty()) people = PerceptualData::read(options.perceptualDir);
  const Study s = readRows(rows);
  const RankTests t = rankTests(s);
  const VerdictCounts verdicts = verdictCounts(s);
  Json results;
  results["generator"] = "glossy study";
  results["glossy"] = glossyJson();
  if (options.provenance) results["provenance"] = provenanceJson(*options.provenance);
  else results["provenance"] = Json{{"reason", "the rows were analysed without their study file"}};
  results["fits"] = fitsJson(s.all);
  results["seed"] = options.seed;
  results["resamples"] = options.resamples;
  results["interval"] = "95 % percentile bootstrap, materials resampled with their sheets";
  results["counts"] = countsJson(s, verdicts);
  results["renderNoise"] = renderNoiseJson(s);
  results["materials"] = perMaterial(s);

  step(2, "per-model and per-lighting intervals");
  results["models"] = perModel(s, t, options);
  addRankTests(s, t, results);
  std::vector<std::string> rankOrder;
  for (std::size_t k : t.rankOrder) rankOrder.push_back(s.models[k]);
  const LightingAnalysis lighting = analyseLighting(s.used, rankOrder, options.resamples, options.seed);
  results["lighting"] = lighting.json;

  step(3, "pairwise shares of materials");
  results["closerThan"] = closerThan(s, options);

  step(4, "BRDF-space against image error");
  std::string claimHeadline, peopleHeadline;
  Json differences = Json::array();
  results["brdfVsImage"] = brdfVsImage(s, options, differences, claimHeadline);
  results["e2MinusE1"] = differences;

  step(5, "against people");
  std::vector<PerceptualSeries> series;
  results["againstPeople"] = againstPeople(s, options, people ? &*people : nullptr, peopleHeadline, series);
  PeopleAnalysis within;
  if (people) {
    within = closestToPeople(s.used, *people, options.resamples, options.seed);
    results["againstPeople"]["withinMaterial"] = within.json;
    peopleHeadline += (peopleHeadline.empty() ? "" : "\n") + within.headline;
    if (!peopleHeadline.empty() && peopleHeadline.back() == '\n') peopleHeadline.pop_back();
  }
  const std::string summary = summaryText(s, t, verdicts, results, lighting.headline, claimHeadline, peopleHeadline);
  results["summary"] = summary;

  step(6, "figures and files");
  const std::vector<StudyFigure> figures = studyFigures(s, t, options, series);
  return writeAnalysis(folder, s, summary, results, figures, lighting, within, options);
}

}  // namespace glossy::study
