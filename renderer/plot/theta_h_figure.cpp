// The θ_h slices: ρ(θ_h; θ_d, φ_d = 90°) for every BRDF, four θ_d as small multiples with one log ρ axis,
// θ_h on MERL's square-root scale. BRDF Explorer's θ_h plot, at the difference angles that show the lobe
// head-on (1°), at mid angles (30°, 60°) and toward grazing (80°) where the models' Fresnel terms part.
#include "materials/core/text.h"
#include "renderer/plot/figures.h"
#include "renderer/plot/plot_csv.h"
#include "renderer/plot/rusinkiewicz.h"

#include <cmath>
#include <limits>

namespace glossy::plot {

namespace {

constexpr double kThetaD[] = {1.0, 30.0, 60.0, 80.0};
constexpr int kSamples = 400;  // θ_h = 90° (k/400)²: even steps on the √ axis, 4.4 per MERL bin

}  // namespace

PlotFigure thetaHFigure(const PlotSet& set) {
  const auto brdfs = set.present();
  std::vector<std::string> columns = {"Lx", "Ly", "Lz", "Vx", "Vy", "Vz", "theta_d_deg", "theta_h_deg", "phi_d_deg"};
  for (const PlotBrdf* b : brdfs) columns.push_back(b->panel.label);
  CsvTable csv(columns);

  // values[slice][brdf][k]
  std::vector<std::vector<std::vector<Point>>> values(std::size(kThetaD), std::vector<std::vector<Point>>(brdfs.size()));
  double peak = 0.0;
  for (size_t s = 0; s < std::size(kThetaD); ++s)
    for (int k = 0; k <= kSamples; ++k) {
      const double f = double(k) / kSamples, thetaH = 90.0 * f * f;
      const auto [L, V] = directionsFromHalfDiff(thetaH * kDeg, (kThetaD[s] + kInsideBinDeg) * kDeg, (90.0 + kInsideBinDeg) * kDeg);
      if (L.z <= 0.0 || V.z <= 0.0) continue;
      std::vector<double> row = {L.x, L.y, L.z, V.x, V.y, V.z, kThetaD[s] + kInsideBinDeg, thetaH, 90.0 + kInsideBinDeg};
      for (size_t b = 0; b < brdfs.size(); ++b) {
        const double v = set.value(*brdfs[b], L, V);
        row.push_back(v);
        values[s][b].push_back({thetaH, v});
        if (v > 0.0 && std::isfinite(v)) peak = std::max(peak, v);
      }
      csv.add(row);
    }
  // The axis reaches down to the lowest floor of any curve in any slice: the diffuse floors of a chrome show.
  const auto [lo, hi] = decadeRange(lowestFloor(values), peak, 3, set.decades);
  GridLayout g;
  g.columns = 2;
  g.rows = 2;
  const std::vector<std::string> caption = {
      "ρ(θh, θd, φd = 90°) against the half-vector angle θh at four difference angles θd (θh on a square-root scale, "
      "as MERL bins it; ρ on a log scale, in 1/sr, from " + set.decadesText(lo, hi, "down to the lowest curve's floor") + "). Measured data are MERL's nearest bin, so they step (θd and φd are "
      "taken 1e-6° inside the bins these angles begin); a gap is an unmeasured bin. Metric: none (values, not errors).",
      set.fitsLine(), set.sourceLine()};
  const std::string title = "θh slices of " + set.material + " (" + channelName(set.channel) + ")";
  SvgDocument svg = gridFigure(g, title, caption);
  for (size_t s = 0; s < std::size(kThetaD); ++s) {
    PlotArea area{g.panelX(int(s)), g.panelY(int(s)), g.panelW, g.panelH, sqrtDegreesAxis("θh (degrees, √ scale)"),
                  logAxis(lo, hi, "ρ (1/sr)")};
    const std::string clip = "clip" + std::to_string(s);
    area.draw(svg, formatted("θd = %g°, φd = 90°", kThetaD[s]), clip);
    // Measured last, so the data lie over the fits.
    for (size_t b = brdfs.size(); b-- > 0;) drawCurve(svg, area, values[s][b], brdfs[b]->style(), clip);
  }
  drawLegend(svg, g.legendX(), g.top, g.legendW, set.legend());
  drawCaption(svg, 24.0, g.captionY(), g.width() - 48.0, caption);
  return {"theta_h", "theta_h", title, caption, svg.str(), csv.str()};
}

}  // namespace glossy::plot
