// The image slice (BRDF Explorer's): ρ over MERL's (θ_h, θ_d) bins at φ_d = 90°, θ_h on MERL's square-root
// axis so every bin is one equal cell, colour = log ρ on one scale shared by the material's figures; beside
// it, for a fit, log10(ρ_fit / ρ_measured) on a diverging map, where a fit is too bright (red) or too dark
// (blue) across the whole domain at a glance. At φ_d = 90° no pair of the slice is below the horizon.
#include "materials/core/text.h"
#include "renderer/image/colour_maps.h"
#include "renderer/plot/figures.h"
#include "renderer/plot/plot_csv.h"
#include "renderer/plot/rusinkiewicz.h"

#include <cmath>
#include <algorithm>
#include <limits>

namespace glossy::plot {

namespace {

constexpr int kN = 90;             // MERL's θ_h and θ_d bins
constexpr double kCell = 3.0;      // px per bin
constexpr double kSide = kN * kCell;  // a slice's width and height, px
constexpr double kRatioDecades = 1.0;  // the diverging map spans ×0.1 … ×10
constexpr const char* kNoData = "#bdbdbd";

double thetaHOf(int i) { const double f = (i + 0.5) / kN; return 90.0 * f * f; }
double thetaDOf(int j) { return j + 0.5; }

using Grid = std::vector<double>;  // [i_θh + 90 i_θd]

// Cells of `colourAt(i, j)` as rects, a row's equal neighbours merged; θ_d grows upward.
void drawCells(SvgDocument& svg, double x, double y, const std::function<std::string(int, int)>& colourAt) {
  svg.beginGroup("shape-rendering=\"crispEdges\"");
  for (int j = 0; j < kN; ++j) {
    const double rowY = y + (kN - 1 - j) * kCell;
    for (int i = 0; i < kN;) {
      const std::string c = colourAt(i, j);
      int end = i + 1;
      while (end < kN && colourAt(end, j) == c) ++end;
      svg.rect(x + i * kCell, rowY, (end - i) * kCell, kCell, c);
      i = end;
    }
  }
  svg.endGroup();
}

PlotArea sliceArea(double x, double y) {
  PlotArea a{x, y, kSide, kSide, sqrtDegreesAxis("θh (degrees, √ scale)"), linearAxis(0.0, 90.0, 15.0, 0, "θd (degrees)")};
  a.grid = false;
  return a;
}

double logRatio(double v, double ref) {
  return v > 0.0 && ref > 0.0 && std::isfinite(v) && std::isfinite(ref) ? std::log10(v / ref) : std::nan("");
}

std::string ratioColour(double r) {
  return std::isfinite(r) ? hexColour(divergingColour(std::clamp(r / kRatioDecades, -1.0, 1.0))) : std::string(kNoData);
}

// Every BRDF's slice, on the colour scale they share.
struct Slices {
  std::vector<std::pair<Vec3, Vec3>> pairs;  // each bin's directions, [i_θh + 90 i_θd]
  std::vector<Grid> grids;                   // per BRDF present
  int lo, hi;                                // the colour scale's decades
  std::string scale;                         // the colour scale as the captions state it
};

Slices sampleSlices(const PlotSet& set, const std::vector<const PlotBrdf*>& brdfs) {
  std::vector<Grid> grids(brdfs.size(), Grid(kN * kN));
  std::vector<std::pair<Vec3, Vec3>> pairs(kN * kN);
  std::vector<double> positive;
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) pairs[size_t(i + kN * j)] = directionsFromHalfDiff(thetaHOf(i) * kDeg, thetaDOf(j) * kDeg, (90.0 + kInsideBinDeg) * kDeg);
  for (size_t b = 0; b < brdfs.size(); ++b)
    for (size_t k = 0; k < pairs.size(); ++k) {
      const double v = set.value(*brdfs[b], pairs[k].first, pairs[k].second);
      grids[b][k] = v;
      if (v > 0.0 && std::isfinite(v)) positive.push_back(v);
    }
  // The colour scale spans the decades holding the 0.5th to the 99.5th percentile of the values: the few
  // grazing bins where a fit's Fresnel and shadowing terms blow up (10^6 at θ_d = 89.5°) would otherwise push
  // everything else into one colour. Values beyond are clamped, as the colour bar's end labels say.
  // --decades: that many decades below the top instead.
  auto quantile = [&](double q) {
    if (positive.empty()) return 1.0;
    const size_t n = std::min(positive.size() - 1, size_t(q * double(positive.size())));
    std::nth_element(positive.begin(), positive.begin() + std::ptrdiff_t(n), positive.end());
    return positive[n];
  };
  const double low = quantile(0.005), high = quantile(0.995);
  const auto [lo, hi] = decadeRange(low, high, 2, set.decades);
  return {std::move(pairs), std::move(grids), lo, hi, set.decadesText(lo, hi, "the decades holding its 0.5th to 99.5th percentile")};
}

// A slice's numbers; with the measured slice m, its value and the log-ratio to it too.
CsvTable sliceCsv(const Slices& s, const PlotBrdf& brdf, const Grid& g, const Grid* m) {
  std::vector<std::string> columns = {"Lx", "Ly", "Lz", "Vx", "Vy", "Vz", "theta_h_deg", "theta_d_deg", "phi_d_deg", brdf.panel.label};
  if (m) columns.insert(columns.end(), {"Measured", "log10_ratio"});
  CsvTable csv(columns);
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i) {
      const size_t k = size_t(i + kN * j);
      const auto& [L, V] = s.pairs[k];
      std::vector<double> row = {L.x, L.y, L.z, V.x, V.y, V.z, thetaHOf(i), thetaDOf(j), 90.0 + kInsideBinDeg, g[k]};
      if (m) row.insert(row.end(), {(*m)[k], logRatio(g[k], (*m)[k])});
      csv.add(row);
    }
  return csv;
}

std::vector<std::string> sliceCaption(const PlotSet& set, const PlotBrdf& brdf, const std::string& scale, bool twoPanels, bool withRatio) {
  std::vector<std::string> caption = {
      std::string(twoPanels ? "Left: " : "") + "ρ(θh, θd, φd = 90°) of " + brdf.panel.label + " at the centres of MERL's bins (θh on a square-root axis, "
      "as MERL bins it, so every bin is one cell), colour log10 ρ in 1/sr on one scale for all of " + set.material +
      "'s image slices, " + scale + " (values beyond take the end colours). Grey: no value (an unmeasured bin)."};
  if (withRatio)
    caption.push_back("Right: log10(ρ_" + brdf.panel.label + " / ρ_Measured): red where the fit is brighter than the data, "
                      "blue where darker, white where they agree; clamped at ×10 and ×0.1; grey where the data have no value.");
  else if (twoPanels)
    caption.push_back("The log-ratio to measured data is not drawn: measured data: " + set.measuredLabel + ".");
  if (!brdf.isMeasured)
    caption.push_back("Fit " + brdf.panel.label + " (" + brdf.panel.fit + "; the metric is the one it was fitted under, Löw et al. 2012).");
  caption.push_back(set.sourceLine());
  return caption;
}

// The left panel: the slice's values, with its colour bar.
void drawValuePanel(SvgDocument& svg, double x, double top, const Slices& s, const PlotBrdf& brdf, const Grid& g) {
  drawCells(svg, x, top, [&](int i, int j) {
    const double v = g[size_t(i + kN * j)];
    if (!(v > 0.0) || !std::isfinite(v)) return std::string(kNoData);
    return hexColour(viridisColour((std::log10(v) - s.lo) / (s.hi - s.lo)));
  });
  sliceArea(x, top).draw(svg, brdf.panel.label + ": ρ", "clip0");
  std::vector<std::pair<double, Tick>> ticks;
  for (int k = s.lo; k <= s.hi; ++k)
    ticks.push_back({double(k - s.lo) / (s.hi - s.lo), {std::pow(10.0, k), k == s.hi ? "≥ 10" : k == s.lo ? "≤ 10" : "10", std::to_string(k)}});
  drawColourBar(svg, x + kSide + 16.0, top, 16.0, kSide,
                [](double t) { return hexColour(viridisColour(t)); }, ticks, "ρ (1/sr)");
}

// The right panel: the log-ratio of slice g to the measured slice m, with its colour bar, or without m a
// box saying why it is not drawn.
void drawRatioPanel(SvgDocument& svg, double x, double top, const Grid& g, const Grid* m) {
  if (!m) {
    svg.rect(x, top, kSide, kSide, "#f7f7f7", "#bbbbbb", 1.0);
    TextStyle note{12.5, Anchor::Middle, false, "#666666"};
    svg.text({x + kSide / 2, top + kSide / 2 - 8.0}, "no log-ratio:", note);
    svg.text({x + kSide / 2, top + kSide / 2 + 10.0}, "no measured data", note);
    return;
  }
  drawCells(svg, x, top, [&](int i, int j) {
    const size_t k = size_t(i + kN * j);
    return ratioColour(logRatio(g[k], (*m)[k]));
  });
  sliceArea(x, top).draw(svg, "log-ratio to Measured", "clip1");
  std::vector<std::pair<double, Tick>> rticks;
  for (double f : {0.1, 0.3, 1.0, 3.0, 10.0})
    rticks.push_back({0.5 + 0.5 * std::log10(f) / kRatioDecades, {f, formatted("×%g", f), ""}});
  drawColourBar(svg, x + kSide + 16.0, top, 16.0, kSide,
                [](double t) { return hexColour(divergingColour(2.0 * t - 1.0)); }, rticks, "ρ_fit / ρ_measured (log scale)");
}

// A BRDF's figure: its slice g, and beside it, for a fit, its log-ratio to the measured slice (null when
// there is none).
PlotFigure sliceFigure(const PlotSet& set, const Slices& s, const PlotBrdf& brdf, const Grid& g, const Grid* measured) {
  const bool twoPanels = &brdf != set.measured();
  const Grid* m = twoPanels ? measured : nullptr;
  const CsvTable csv = sliceCsv(s, brdf, g, m);
  const std::vector<std::string> caption = sliceCaption(set, brdf, s.scale, twoPanels, m != nullptr);

  const double left = 90.0, top = 78.0;
  const double secondX = left + kSide + 16.0 + 16.0 + 150.0;
  const std::string title = "Image slice of " + brdf.panel.label + ", " + set.material + " (" + channelName(set.channel) + ")";
  // Room for the title (bold 17 px, about 0.62 em a character) when there is one panel only.
  const double width = std::max(twoPanels ? secondX + kSide + 16.0 + 16.0 + 110.0 : left + kSide + 16.0 + 16.0 + 110.0,
                                48.0 + 17.0 * 0.62 * double(title.size()));
  const double captionY = top + kSide + 62.0;
  SvgDocument svg(width, captionY + captionHeight(width - 48.0, caption) + 16.0);
  drawFigureTitle(svg, title);
  drawValuePanel(svg, left, top, s, brdf, g);
  if (twoPanels) drawRatioPanel(svg, secondX, top, g, m);
  drawCaption(svg, 24.0, captionY, width - 48.0, caption);
  return {"image_slice", "image_slice_" + brdf.panel.layer, title, caption, svg.str(), csv.str()};
}

}  // namespace

std::vector<PlotFigure> imageSliceFigures(const PlotSet& set) {
  const auto brdfs = set.present();
  const Slices slices = sampleSlices(set, brdfs);
  const Grid* m = nullptr;
  for (size_t b = 0; b < brdfs.size(); ++b)
    if (brdfs[b] == set.measured()) m = &slices.grids[b];
  std::vector<PlotFigure> figures;
  for (size_t b = 0; b < brdfs.size(); ++b) figures.push_back(sliceFigure(set, slices, *brdfs[b], slices.grids[b], m));
  return figures;
}

}  // namespace glossy::plot
