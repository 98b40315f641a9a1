#include "renderer/study/study_figures.h"

#include "materials/core/text.h"
#include "renderer/image/colour_maps.h"
#include "renderer/plot/figure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace glossy::study {

using namespace glossy::plot;

namespace {

// The decades of a log axis over the positive values of `columns` (at least one decade wide).
std::pair<int, int> decadesOf(const std::vector<double>& values) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (double v : values)
    if (v > 0.0 && std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!(hi > 0.0)) return {-3, 0};
  int dlo = int(std::floor(std::log10(lo) + 1e-9)), dhi = int(std::ceil(std::log10(hi) - 1e-9));
  if (dhi <= dlo) dhi = dlo + 1;
  return {dlo, dhi};
}

std::vector<double> valuesOf(const std::vector<std::vector<std::optional<double>>>& column) {
  std::vector<double> out;
  for (const auto& row : column)
    for (const auto& v : row)
      if (v) out.push_back(*v);
  return out;
}

std::vector<LegendEntry> legendOf(const MaterialTable& t) {
  std::vector<LegendEntry> out;
  for (const ModelStyle& m : t.models) out.push_back({m.label, m.style, true, m.note});
  return out;
}

double tickStep(int n) {
  for (double s : {1.0, 2.0, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0, 200.0, 500.0})
    if (n / s <= 10.0) return s;
  return 1000.0;
}

}  // namespace

std::string errorCurvesCaption(const MaterialTable& t, const std::string& referenceModel) {
  const auto ref = std::find_if(t.models.begin(), t.models.end(), [&](const ModelStyle& m) { return m.label == referenceModel; });
  const std::string refName = t.models.empty() ? std::string("—") : t.models[ref == t.models.end() ? 0 : std::size_t(ref - t.models.begin())].label;
  return "The noise-free relative RMSE r* of every model on every material (averaged over the material's sheets), "
         "materials sorted by " + refName + "'s error" + (ref == t.models.end() && !t.models.empty() ? " (" + referenceModel + " is not in the study)" : "") +
         "; log scale. A curve below another is the closer model on that material; a circle on the axis floor is an r* of 0 "
         "(an estimate below 0 clamped to it); a gap is a material the model was not rendered for.";
}

std::string heatMapCaption() {
  return "r* (noise-free relative RMSE, averaged over each material's sheets) of every model (columns) on every material "
         "(rows), on a log colour scale; an r* of 0 (an estimate below 0 clamped to it) takes the scale's lowest colour and "
         "is marked 0; grey: not rendered.";
}

std::string criticalDifferenceCaption(int materials, const std::string& test) {
  return "Mean rank of each model's r* over " + std::to_string(materials) +
         " materials (1 = closest; Friedman). Models joined by a bar are not significantly different under pairwise "
         "Wilcoxon signed-rank tests (" + test + ") with Holm's correction at α = 0.05 (Demšar 2006; cliques as Benavoli et al. 2016 recommend).";
}

std::string brdfVsImageCaption() {
  return "Each fit's BRDF-space error (E1 left, E2 right) against its image-space error r* on each material (averaged over "
         "the material's sheets), log-log. If the BRDF metric predicted what the image shows, the points of a material "
         "would rise together; results.json gives the rank correlations with their intervals. An r* of 0 is drawn on the "
         "r* axis's floor.";
}

std::string perceptualCaption() {
  return "glossy's figures of the fits the perceptual dataset shares (x, log scale) against the distance people perceived "
         "between the fit's render and the measured material (y; 0 = indistinguishable, 1 = most different), one point "
         "per MERL material. Perceived distances: Lavoué, Bonneel, Farrugia, Soler, CGF 40(2), 2021.";
}

std::string errorCurvesSvg(const MaterialTable& t, const std::string& referenceModel) {
  const auto ref = std::find_if(t.models.begin(), t.models.end(), [&](const ModelStyle& m) { return m.label == referenceModel; });
  const std::size_t r = ref == t.models.end() ? 0 : std::size_t(ref - t.models.begin());
  // Materials in the order of the reference model's error (materials it lacks last, by name).
  std::vector<std::size_t> order(t.materials.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const auto& x = t.models.empty() ? std::optional<double>() : t.rrmse[a][r];
    const auto& y = t.models.empty() ? std::optional<double>() : t.rrmse[b][r];
    if (x && y) return *x < *y;
    return bool(x) && !y;
  });
  const std::string refName = t.models.empty() ? std::string("—") : t.models[r].label;
  const std::vector<std::string> caption = {errorCurvesCaption(t, referenceModel)};
  GridLayout g;
  g.panelW = 620.0;
  g.panelH = 300.0;
  const std::string title = "Per-material error, sorted by " + refName;
  SvgDocument svg = gridFigure(g, title, caption);
  const auto [lo, hi] = decadesOf(valuesOf(t.rrmse));
  const int n = int(t.materials.size());
  PlotArea area{g.panelX(0), g.panelY(0), g.panelW, g.panelH,
                linearAxis(0.0, std::max(1.0, std::ceil(n / tickStep(n)) * tickStep(n)), tickStep(n), 0, "material (rank by " + refName + ")"),
                logAxis(lo, hi, "r* (rel. RMSE)")};
  area.draw(svg, "", "clip0");
  // A zero sits on the axis's floor, joined to its neighbours and circled: a log axis has no place for it,
  // and a gap would read as a material not rendered.
  const double floor = std::pow(10.0, lo);
  for (std::size_t k = 0; k < t.models.size(); ++k) {
    std::vector<Point> pts, zeros;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const auto& v = t.rrmse[order[i]][k];
      pts.push_back({double(i + 1), v ? std::max(*v, floor) : std::nan("")});
      if (v && *v <= 0.0) zeros.push_back(pts.back());
    }
    drawCurve(svg, area, pts, t.models[k].style, "clip0");
    for (const Point& z : zeros)
      if (const Point at = area.at(z.x, z.y); std::isfinite(at.x) && std::isfinite(at.y)) svg.circle(at, 3.2, t.models[k].style.colour, 1.4);
  }
  drawLegend(svg, g.legendX(), g.top, g.legendW, legendOf(t));
  drawCaption(svg, 24.0, g.captionY(), g.width() - 48.0, caption);
  return svg.str();
}

std::string heatMapSvg(const MaterialTable& t) {
  const double cellW = 70.0, cellH = std::clamp(600.0 / std::max<std::size_t>(1, t.materials.size()), 6.0, 18.0);
  const double left = 190.0, top = 130.0;
  const double gridW = cellW * double(t.models.size()), gridH = cellH * double(t.materials.size());
  const std::vector<std::string> caption = {heatMapCaption()};
  const double width = std::max(left + gridW + 160.0, 520.0);
  SvgDocument svg(width, top + gridH + 30.0 + captionHeight(width - 48.0, caption) + 16.0);
  drawFigureTitle(svg, "Material × model error");
  const auto [lo, hi] = decadesOf(valuesOf(t.rrmse));
  // Copied, not captured: clang before 16 cannot capture a structured binding (the fuzzers' build is clang).
  const auto tOf = [lo = lo, hi = hi](double v) { return std::clamp((std::log10(v) - lo) / double(hi - lo), 0.0, 1.0); };
  for (std::size_t k = 0; k < t.models.size(); ++k)
    svg.text({left + cellW * (double(k) + 0.5), top - 8.0}, t.models[k].label, {11.0, Anchor::Start, false, "#222222", -45.0});
  const bool labelRows = cellH >= 9.0;
  svg.beginGroup("shape-rendering=\"crispEdges\"");
  for (std::size_t i = 0; i < t.materials.size(); ++i) {
    for (std::size_t k = 0; k < t.models.size(); ++k) {
      const auto& v = t.rrmse[i][k];
      // A zero is the scale's lowest colour (marked below), not the grey of a model not rendered.
      svg.rect(left + cellW * double(k), top + cellH * double(i), cellW, cellH,
               !v ? std::string("#dddddd") : hexColour(viridisColour(*v > 0.0 ? tOf(*v) : 0.0)));
    }
  }
  svg.endGroup();
  for (std::size_t i = 0; i < t.materials.size(); ++i)
    for (std::size_t k = 0; k < t.models.size(); ++k)
      if (const auto& v = t.rrmse[i][k]; v && *v <= 0.0)
        svg.text({left + cellW * (double(k) + 0.5), top + cellH * (double(i) + 0.5) + std::min(4.0, cellH / 2.0 - 1.0)}, "0",
                 {std::min(11.0, std::max(cellH - 1.0, 5.0)), Anchor::Middle, false, "#ffffff"});
  if (labelRows)
    for (std::size_t i = 0; i < t.materials.size(); ++i)
      svg.text({left - 6.0, top + cellH * (double(i) + 0.75)}, t.materials[i], {std::min(11.0, cellH - 1.0), Anchor::End});
  std::vector<std::pair<double, Tick>> ticks;
  for (int d = lo; d <= hi; ++d) ticks.push_back({double(d - lo) / double(hi - lo), {std::pow(10.0, d), "10", std::to_string(d)}});
  drawColourBar(svg, left + gridW + 20.0, top, 16.0, std::max(gridH, 120.0), [](double x) { return hexColour(viridisColour(x)); },
                ticks, "r*");
  drawCaption(svg, 24.0, top + std::max(gridH, 120.0) + 30.0, width - 48.0, caption);
  return svg.str();
}

std::string criticalDifferenceSvg(const std::vector<CdModel>& models, const std::vector<std::pair<int, int>>& cliques,
                                  int materials, const std::string& test) {
  const std::size_t k = models.size();
  const double width = 760.0, left = 150.0, right = width - 150.0, axisY = 110.0;
  const std::vector<std::string> caption = {criticalDifferenceCaption(materials, test)};
  const double labelsH = 30.0 + 22.0 * double((k + 1) / 2);
  const double barsH = 14.0 * double(cliques.size()) + 20.0;
  SvgDocument svg(width, axisY + std::max(labelsH, barsH) + 30.0 + captionHeight(width - 48.0, caption) + 16.0);
  drawFigureTitle(svg, "Critical-difference diagram");
  if (k < 2) {
    svg.text({24.0, axisY}, "No ranking: fewer than two models on materials with every model.", {13.0});
    drawCaption(svg, 24.0, axisY + 40.0, width - 48.0, caption);
    return svg.str();
  }
  const auto xOf = [&](double rank) { return left + (rank - 1.0) / double(k - 1) * (right - left); };
  svg.line({left, axisY}, {right, axisY}, "#222222", 1.2);
  for (std::size_t r = 1; r <= k; ++r) {
    svg.line({xOf(double(r)), axisY - 6.0}, {xOf(double(r)), axisY}, "#222222", 1.0);
    svg.text({xOf(double(r)), axisY - 10.0}, std::to_string(r), {12.0, Anchor::Middle});
  }
  // The better half labelled on the left, the rest on the right, each on its own line.
  for (std::size_t i = 0; i < k; ++i) {
    const bool leftSide = i < (k + 1) / 2;
    const std::size_t row = leftSide ? i : k - 1 - i;
    const double y = axisY + 30.0 + 22.0 * double(row);
    const double x = xOf(models[i].meanRank);
    const double end = leftSide ? left - 10.0 : right + 10.0;
    svg.line({x, axisY}, {x, y}, "#444444", 1.0);
    svg.line({x, y}, {end, y}, "#444444", 1.0);
    svg.text({leftSide ? end - 4.0 : end + 4.0, y + 4.0}, models[i].label + formatted(" (%.2f)", models[i].meanRank),
             {12.0, leftSide ? Anchor::End : Anchor::Start});
  }
  for (std::size_t c = 0; c < cliques.size(); ++c) {
    const double y = axisY + 12.0 + 8.0 * double(c);
    svg.line({xOf(models[std::size_t(cliques[c].first)].meanRank) - 3.0, y},
             {xOf(models[std::size_t(cliques[c].second)].meanRank) + 3.0, y}, "#000000", 3.0);
  }
  drawCaption(svg, 24.0, axisY + std::max(labelsH, barsH) + 30.0, width - 48.0, caption);
  return svg.str();
}

std::string brdfVsImageSvg(const MaterialTable& t) {
  const std::vector<std::string> caption = {brdfVsImageCaption()};
  GridLayout g;
  g.columns = 2;
  SvgDocument svg = gridFigure(g, "BRDF error against image error", caption);
  const auto [ylo, yhi] = decadesOf(valuesOf(t.rrmse));
  const std::vector<std::vector<std::optional<double>>>* xs[] = {&t.e1, &t.e2};
  const char* names[] = {"E1", "E2"};
  for (int p = 0; p < 2; ++p) {
    const auto [xlo, xhi] = decadesOf(valuesOf(*xs[p]));
    PlotArea area{g.panelX(p), g.panelY(p), g.panelW, g.panelH, logAxis(xlo, xhi, std::string(names[p]) + " (BRDF space)"),
                  logAxis(ylo, yhi, "r* (image space)")};
    const std::string clip = "clip" + std::to_string(p);
    area.draw(svg, names[p] + std::string(" against r*"), clip);
    for (std::size_t i = 0; i < t.materials.size(); ++i)
      for (std::size_t k = 0; k < t.models.size(); ++k) {
        const auto& x = (*xs[p])[i][k];
        const auto& y = t.rrmse[i][k];
        if (!x || !y) continue;
        const Point at = area.at(*x, std::max(*y, std::pow(10.0, ylo)));
        if (std::isfinite(at.x) && std::isfinite(at.y)) svg.circle(at, 2.6, t.models[k].style.colour, 1.2);
      }
  }
  drawLegend(svg, g.legendX(), g.top, g.legendW, legendOf(t));
  drawCaption(svg, 24.0, g.captionY(), g.width() - 48.0, caption);
  return svg.str();
}

std::string perceptualSvg(const std::vector<PerceptualSeries>& series, const std::vector<std::string>& figureNames) {
  const std::vector<std::string> caption = {perceptualCaption()};
  GridLayout g;
  g.columns = 2;
  g.rows = 2;
  SvgDocument svg = gridFigure(g, "glossy's figures against perceived distance", caption);
  for (std::size_t f = 0; f < figureNames.size() && f < 4; ++f) {
    std::vector<double> xs;
    for (const auto& s : series)
      if (f < s.points.size())
        for (const Point& p : s.points[f]) xs.push_back(p.x);
    const auto [xlo, xhi] = decadesOf(xs);
    PlotArea area{g.panelX(int(f)), g.panelY(int(f)), g.panelW, g.panelH, logAxis(xlo, xhi, figureNames[f]),
                  linearAxis(0.0, 1.0, 0.2, 1, "perceived distance")};
    const std::string clip = "clip" + std::to_string(f);
    area.draw(svg, figureNames[f], clip);
    for (const auto& s : series)
      if (f < s.points.size())
        for (const Point& p : s.points[f]) {
          const Point at = area.at(p.x, p.y);
          if (std::isfinite(at.x) && std::isfinite(at.y)) svg.circle(at, 2.6, s.style.colour, 1.2);
        }
  }
  std::vector<LegendEntry> legend;
  for (const auto& s : series) legend.push_back({s.name, s.style, true, s.note});
  drawLegend(svg, g.legendX(), g.top, g.legendW, legend);
  drawCaption(svg, 24.0, g.captionY(), g.width() - 48.0, caption);
  return svg.str();
}

}  // namespace glossy::study
