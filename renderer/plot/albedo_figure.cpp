// Directional albedo against the viewing angle θ_V: how much light each BRDF reflects in all, which a fit
// can match at the peak and still miss (too much energy at grazing, too little in the tail). Every curve,
// the measured one included, comes from the same quadrature (directional_albedo.h), the measured one over
// the table's nearest-bin values, its unmeasured bins counting as 0 (as they render).
#include "materials/core/text.h"
#include "renderer/plot/directional_albedo.h"
#include "renderer/plot/figures.h"
#include "renderer/plot/plot_csv.h"

#include <tbb/parallel_for.h>

#include <cmath>

namespace glossy::plot {

namespace {

std::vector<double> viewAngles() {
  std::vector<double> a;
  for (int k = 0; k < 36; ++k) a.push_back(2.5 * k);
  a.push_back(89.0);  // 90° itself has no albedo: V on the horizon
  return a;
}

}  // namespace

PlotFigure albedoFigure(const PlotSet& set) {
  const auto brdfs = set.present();
  const std::vector<double> angles = viewAngles();
  std::vector<std::vector<double>> albedo(brdfs.size(), std::vector<double>(angles.size()));
  tbb::parallel_for(size_t(0), brdfs.size() * angles.size(), [&](size_t k) {
    const size_t b = k / angles.size(), a = k % angles.size();
    albedo[b][a] = directionalAlbedo([&](const Vec3& L, const Vec3& V) { return set.value(*brdfs[b], L, V); }, angles[a] * kDeg);
  });

  std::vector<std::string> columns = {"theta_v_deg", "Vx", "Vy", "Vz"};
  for (const PlotBrdf* b : brdfs) columns.push_back(b->panel.label);
  CsvTable csv(columns);
  double peak = 0.0;
  for (size_t a = 0; a < angles.size(); ++a) {
    const double t = angles[a] * kDeg;
    std::vector<double> row = {angles[a], std::sin(t), 0.0, std::cos(t)};
    for (size_t b = 0; b < brdfs.size(); ++b) {
      row.push_back(albedo[b][a]);
      peak = std::max(peak, albedo[b][a]);
    }
    csv.add(row);
  }

  GridLayout g;
  g.panelW = 560.0;
  g.panelH = 340.0;
  const double top = niceCeil(peak * 1.05);
  const double step = niceCeil(top / 6.0);
  const int decimals = std::max(0, int(std::ceil(-std::log10(step) + 1e-9)) + (step / std::pow(10.0, std::floor(std::log10(step))) == 2.5 ? 1 : 0));
  PlotArea area{g.panelX(0), g.panelY(0), g.panelW, g.panelH, linearAxis(0.0, 90.0, 15.0, 0, "θV, viewing angle from the normal (degrees)"),
                linearAxis(0.0, std::ceil(top / step - 1e-9) * step, step, decimals, "directional albedo a(θV) = ∫ρ cos θL dωL")};
  const std::vector<std::string> caption = {
      "Directional albedo, the share of light from direction V that the surface reflects (the " + channelName(set.channel) +
          " channel; unitless), by deterministic quadrature over the half-vector (every BRDF alike, the measured one "
          "from the table's nearest bins, its unmeasured bins counting as 0). θV = 0 is the value of the spec's "
          "reference table for the R channel. Metric: none (values, not errors).",
      set.fitsLine(), set.sourceLine()};
  const std::string title = "Directional albedo of " + set.material + " (" + channelName(set.channel) + ")";
  SvgDocument svg = gridFigure(g, title, caption);
  area.draw(svg, "", "clip0");
  for (size_t b = brdfs.size(); b-- > 0;) {
    std::vector<Point> pts;
    for (size_t a = 0; a < angles.size(); ++a) pts.push_back({angles[a], albedo[b][a]});
    drawCurve(svg, area, pts, brdfs[b]->style(), "clip0");
  }
  drawLegend(svg, g.legendX(), g.top, g.legendW, set.legend());
  drawCaption(svg, 24.0, g.captionY(), g.width() - 48.0, caption);
  return {"albedo", "albedo", title, caption, svg.str(), csv.str()};
}

}  // namespace glossy::plot
