// The study's figures (SVG, drawn with glossy plot's chart parts, renderer/plot/chart.h): the per-material
// error curves, the material × model heat map, the critical-difference diagram, BRDF-space against
// image-space error, and glossy's figures against the perceived distance. Inputs are the analysis' own
// per-material table, so a figure shows exactly the numbers results.json holds.
#pragma once

#include "renderer/plot/chart.h"

#include <optional>
#include <string>
#include <vector>

namespace glossy::study {

// A figure of the analysis: its name, SVG and caption (for results.json, summary.md and the report page).
struct StudyFigure {
  std::string name, svg, caption;
};

struct ModelStyle {
  std::string label;
  plot::CurveStyle style;
  std::string note;  // under its legend entry, e.g. "glossy's fit"
};

// Per material (rows) and model (columns): the figure averaged over the material's sheets.
struct MaterialTable {
  std::vector<std::string> materials;
  std::vector<ModelStyle> models;
  std::vector<std::vector<std::optional<double>>> rrmse, flip, e1, e2;
};

struct CdModel {
  std::string label;
  double meanRank;
};

struct PerceptualSeries {
  std::string name;  // the model's label, e.g. "Microfacet E2"
  std::string note;  // under it in the legend, e.g. "published fit, as ABC"
  plot::CurveStyle style;
  // Per figure (rRMSE, ꟻLIP, E1, E2): (glossy's figure, perceived distance) over the materials.
  std::vector<std::vector<plot::Point>> points;
};

// Each figure's caption, as drawn under it and as results.json, summary.md and the report page give it.
std::string errorCurvesCaption(const MaterialTable& t, const std::string& referenceModel);
std::string heatMapCaption();
std::string criticalDifferenceCaption(int materials, const std::string& test);
std::string brdfVsImageCaption();
std::string perceptualCaption();

// A zero r* (a negative estimate clamped to 0) is a figure, not a gap: the error curves draw it as a point
// on the log axis's floor, the heat map in the scale's lowest colour marked "0". Lines are solid; glossy's
// own fits are told apart in the legend.
std::string errorCurvesSvg(const MaterialTable& t, const std::string& referenceModel);
std::string heatMapSvg(const MaterialTable& t);
// `models` in rank order; `cliques` as [first, last] index ranges of models not significantly different.
std::string criticalDifferenceSvg(const std::vector<CdModel>& models, const std::vector<std::pair<int, int>>& cliques,
                                  int materials, const std::string& test);
std::string brdfVsImageSvg(const MaterialTable& t);
std::string perceptualSvg(const std::vector<PerceptualSeries>& series, const std::vector<std::string>& figureNames);

}  // namespace glossy::study
