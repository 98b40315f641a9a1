#include "renderer/study/study_people_correlations.h"

#include "renderer/sheet/comparison_grid.h"
#include "renderer/study/study_intervals.h"

#include <array>

namespace glossy::study {

namespace {

const char* const kFigureNames[] = {"rrmse", "flip", "E1", "E2"};

// Per material, each figure of exactly this fit's rows (a model's label may cover glossy's fits on other
// materials), averaged over the material's sheets; `label`: the rows' model label (empty: no such rows).
std::vector<std::array<Opt, 4>> figuresOfFit(const Study& s, const PerceptualFit& pf, std::string& label) {
  std::vector<std::array<Opt, 4>> figure(s.materials.size());
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    std::array<std::vector<double>, 4> v;
    for (const StudyRow* r : s.used) {
      if (r->material != s.materials[i] || r->fit != pf.fit || r->fitSource != pf.fitSource) continue;
      if (label.empty()) label = r->label;
      const Opt values[] = {r->rrmse, r->flip, r->e1, r->e2};
      for (std::size_t f = 0; f < 4; ++f)
        if (values[f]) v[f].push_back(*values[f]);
    }
    for (std::size_t f = 0; f < 4; ++f) figure[i][f] = meanOf(v[f]);
  }
  return figure;
}

// The figure whose Spearman ρ with the perceived distance is the highest so far, with its interval.
struct BestFigure {
  std::string name;
  Interval rho;
};

// One figure against the perceived distance over the materials that have both (`points`: (figure,
// distance)): its correlations with their intervals.
Json figureAgainstPeople(const std::vector<plot::Point>& points, const char* figure, const std::string& fit, const AnalysisOptions& o,
                         BestFigure& best) {
  Json jfig;
  jfig["figure"] = figure;
  jfig["materials"] = int(points.size());
  const Interval rho = addCorrelations(
      jfig, points.size(),
      [&](const std::vector<std::size_t>& idx) {
        Pair p;
        for (std::size_t i : idx) {
          p.x.push_back(points[i].x);
          p.y.push_back(points[i].y);
        }
        return p;
      },
      o.resamples, o.seed, "people/" + fit + "/" + figure);
  if (rho.estimate && (best.name.empty() || *rho.estimate > *best.rho.estimate)) best = {figure, rho};
  return jfig;
}

// One of the fits the dataset judged, against people: its figures' correlations with the perceived
// distance across materials, its series of the perceptual figure (in `colour`) and its line of the summary.
Json fitAgainstPeople(const Study& s, const AnalysisOptions& o, const PerceptualData& data, const PerceptualFit& pf, const std::string& colour,
                      std::string& headline, std::vector<PerceptualSeries>& series) {
  std::string label;
  const std::vector<std::array<Opt, 4>> figure = figuresOfFit(s, pf, label);
  Json jf;
  jf["method"] = pf.method;
  jf["fit"] = pf.fit;
  jf["fitSource"] = pf.fitSource;
  if (label.empty()) {
    jf["model"] = nullptr;
    jf["reason"] = "the study has no " + pf.fitSource + " " + pf.fit + " fit";
    return jf;
  }
  jf["model"] = label;
  // The materials with both a glossy figure and a perceived distance.
  std::vector<std::size_t> mats;
  std::vector<double> dist;
  for (std::size_t i = 0; i < s.materials.size(); ++i)
    if (const auto d = data.distance(pf.method, s.materials[i]); d && figure[i][0]) {
      mats.push_back(i);
      dist.push_back(*d);
    }
  jf["materials"] = int(mats.size());
  PerceptualSeries ps;
  ps.name = label;
  ps.note = pf.fitSource + " fit, as " + pf.method;
  const std::string pairName = pf.method + " ↔ " + label + " (" + pf.fitSource + ")";
  ps.style.colour = colour;
  ps.points.resize(std::size(kFigureNames));
  Json figs = Json::array();
  BestFigure best;
  for (std::size_t f = 0; f < std::size(kFigureNames); ++f) {
    for (std::size_t u = 0; u < mats.size(); ++u)
      if (figure[mats[u]][f]) ps.points[f].push_back({*figure[mats[u]][f], dist[u]});
    figs.push_back(figureAgainstPeople(ps.points[f], kFigureNames[f], pf.fit, o, best));
  }
  jf["figures"] = figs;
  jf["agreesBest"] = best.name.empty() ? Json(nullptr) : Json(best.name);
  series.push_back(ps);
  // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) about the one-expression form here.
  if (!headline.empty()) headline += "\n";
  headline += "Against people (" + pairName + ", " + std::to_string(mats.size()) + " MERL materials): ";
  if (best.name.empty())
    headline += "no figure correlates (undefined)";
  else if (best.rho.lo)
    headline += "the figure that agrees best with the perceived distance is " + best.name + ", Spearman ρ " + intervalText(best.rho, "%.3f");
  else  // Without an interval the highest ρ is a description of these materials, not a finding.
    headline += "the highest Spearman ρ with the perceived distance is " + best.name + "'s, " + intervalText(best.rho, "%.3f");
  return jf;
}

}  // namespace

Json againstPeople(const Study& s, const AnalysisOptions& o, const PerceptualData* data, std::string& headline,
                   std::vector<PerceptualSeries>& series) {
  Json out;
  if (!data) {
    out["reason"] = "no perceptual data given";
    return out;
  }
  out["source"] =
      "Lavoué, Bonneel, Farrugia, Soler, \"Perceptual quality of BRDF approximations: dataset and metrics\", "
      "Computer Graphics Forum 40(2), 2021";
  out["note"] =
      "The dataset's ABC rows are Löw et al. 2012's model with the fit published in their supplement (fitted under E2). "
      "Which ABC variant (Smooth Surface or Microfacet) the study used is not stated in the released data and could not "
      "be checked, so both published ABC fits are compared.";
  Json fits = Json::array();
  headline.clear();
  for (const PerceptualFit& pf : perceptualFits()) {
    fits.push_back(fitAgainstPeople(s, o, *data, pf, std::string(fitColour(pf.fit)), headline, series));
  }
  out["fits"] = fits;
  return out;
}

}  // namespace glossy::study
