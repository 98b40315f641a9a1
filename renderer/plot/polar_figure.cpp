// In-plane polar lobes (BRDF Explorer's polar plot): ρ(L, V) cos θ_i for L in the plane of incidence, the
// light a surface sends back toward V from each incident direction, at θ_V ∈ {0°, 30°, 60°, 75°}. θ_i is
// signed: positive on V's side (backscatter), negative on the mirror side, where a glossy lobe peaks at
// θ_i = −θ_V. The radius is log scaled by default (the lobe and the diffuse floor in one picture, decades
// 10^k on the rings) or linear (the lobe's shape as BRDF Explorer draws it).
#include "materials/core/text.h"
#include "renderer/plot/figures.h"
#include "renderer/plot/plot_csv.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glossy::plot {

namespace {

constexpr double kThetaV[] = {0.0, 30.0, 60.0, 75.0};
constexpr double kRadius = 165.0;
constexpr const char* kFrame = "#444444";
constexpr const char* kGrid = "#e3e3e3";

// θ_i every 0.5°, and every 0.02° within 5° of the mirror direction, where the narrowest published lobes
// (a few mrad) live.
std::vector<double> incidentAngles(double thetaV) {
  std::vector<double> a;
  for (int k = -180; k <= 180; ++k) a.push_back(0.5 * k);
  for (int k = -250; k <= 250; ++k) a.push_back(-thetaV + 0.02 * k);
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end(), [](double x, double y) { return std::abs(x - y) < 1e-9; }), a.end());
  a.erase(std::remove_if(a.begin(), a.end(), [](double t) { return std::abs(t) >= 90.0 - 1e-9; }), a.end());
  return a;
}

using Curves = std::vector<std::vector<std::vector<Point>>>;  // [view][brdf] = (θ_i, ρ cos θ_i)

// Every BRDF's lobe at every θ_V, their peak, and the CSV of the values.
struct Lobes {
  CsvTable csv;
  Curves curves;
  double peak;
};

Lobes sampleLobes(const PlotSet& set, const std::vector<const PlotBrdf*>& brdfs) {
  std::vector<std::string> columns = {"Lx", "Ly", "Lz", "Vx", "Vy", "Vz", "theta_v_deg", "theta_i_deg"};
  for (const PlotBrdf* b : brdfs) columns.push_back(b->panel.label);
  CsvTable csv(columns);
  Curves curves(std::size(kThetaV), std::vector<std::vector<Point>>(brdfs.size()));
  double peak = 0.0;
  for (size_t s = 0; s < std::size(kThetaV); ++s) {
    const Vec3 V(std::sin(kThetaV[s] * kDeg), 0.0, std::cos(kThetaV[s] * kDeg));
    for (double ti : incidentAngles(kThetaV[s])) {
      const Vec3 L(std::sin(ti * kDeg), 0.0, std::cos(ti * kDeg));
      if (L.z <= 0.0 || V.z <= 0.0) continue;
      std::vector<double> row = {L.x, L.y, L.z, V.x, V.y, V.z, kThetaV[s], ti};
      for (size_t b = 0; b < brdfs.size(); ++b) {
        const double v = set.value(*brdfs[b], L, V) * L.z;
        row.push_back(v);
        curves[s][b].push_back({ti, v});
        if (v > 0.0 && std::isfinite(v)) peak = std::max(peak, v);
      }
      csv.add(row);
    }
  }
  return {std::move(csv), std::move(curves), peak};
}

// The radius of a value: decades lo to hi (log) or 0 to linearTop (linear) from the centre to the outer ring.
struct RadialAxis {
  RadialScale scale;
  int lo, hi;
  double linearTop;

  // NaN breaks the curve (no value), values under the log scale's floor sit at the centre.
  double radius(double v) const {
    if (!std::isfinite(v) || v < 0.0) return std::nan("");
    if (scale == RadialScale::Linear) return kRadius * std::min(v / linearTop, 1.05);
    if (v <= 0.0) return 0.0;
    return kRadius * std::clamp((std::log10(v) - lo) / double(hi - lo), 0.0, 1.05);
  }

  // Rings: decades (log) or five even steps (linear), each labelled on the baseline to the right.
  std::vector<std::pair<double, Tick>> rings() const {
    std::vector<std::pair<double, Tick>> rings;
    if (scale == RadialScale::Log)
      for (int k = lo; k <= hi; ++k) {
        // Every ring drawn; beyond 6 decades every other one labelled (counting down from the outer), so the labels do not run together.
        const bool labelled = hi - lo <= 6 || (hi - k) % 2 == 0;
        rings.push_back({kRadius * (k - lo) / double(hi - lo), {0.0, labelled ? "10" : "", labelled ? std::to_string(k) : ""}});
      }
    else
      for (int k = 1; k <= 5; ++k) rings.push_back({kRadius * k / 5.0, {0.0, formatted("%g", linearTop * k / 5.0), ""}});
    return rings;
  }
};

// A panel's half disc: its centre on the surface, θ from the normal (up), positive to the right.
struct Dial {
  double cx, cy;

  Point at(double thetaDeg, double r) const { return Point{cx + r * std::sin(thetaDeg * kDeg), cy - r * std::cos(thetaDeg * kDeg)}; }
};

// The axes of the panel at θ_V (its top at `top`): rings, spokes, the surface, the mirror direction, V and
// the panel's heading.
void drawDial(SvgDocument& svg, const Dial& d, const RadialAxis& axis, double thetaV, double top) {
  const double cx = d.cx, cy = d.cy;
  const std::vector<std::pair<double, Tick>> rings = axis.rings();
  for (const auto& [r, tick] : rings) {
    if (r <= 0.0) continue;
    std::vector<Point> arc;
    for (int a = -90; a <= 90; a += 2) arc.push_back(d.at(a, r));
    svg.polyline(arc, kGrid, 1.0);
  }
  for (int a = -90; a <= 90; a += 15) {
    svg.line({cx, cy}, d.at(a, kRadius), kGrid, 1.0);
    if (a % 30 == 0) {
      const Point p = d.at(a, kRadius + 14.0);
      svg.text({p.x, p.y + 4.0}, formatted("%d°", a), {11.0, a < 0 ? Anchor::End : a > 0 ? Anchor::Start : Anchor::Middle, false, "#555555"});
    }
  }
  svg.line({cx - kRadius, cy}, {cx + kRadius, cy}, kFrame, 1.0);  // the surface
  for (const auto& [r, tick] : rings)
    if (!tick.label.empty()) svg.text({cx + r, cy + 15.0}, tick.label, {10.5, Anchor::Middle, false, "#444444"}, tick.superscript);
  svg.text({cx - kRadius, cy + 15.0}, "ρ cos θi:", {10.5, Anchor::Start, false, "#444444"});
  svg.text({cx, cy + 36.0}, "θi (degrees from the normal); radius ρ cos θi (1/sr)", {12.5, Anchor::Middle});
  // The mirror direction and V.
  svg.line({cx, cy}, d.at(-thetaV, kRadius), "#888888", 1.0, "4 3");
  const Point v = d.at(thetaV, kRadius * 1.0);
  svg.line({cx, cy}, v, "#222222", 1.4);
  svg.text(d.at(thetaV + (thetaV > 0 ? 4.0 : 6.0), kRadius - 8.0), "V", {12.0, Anchor::Middle, true, "#222222"});
  svg.text({cx, top - 28.0}, formatted("θV = %g°", thetaV), {14.0, Anchor::Middle, true});
}

// One panel's lobes, curves[brdf], clipped to its half disc: the last BRDF first, so that the first (the
// grid's Measured) lies over the others.
void drawLobes(SvgDocument& svg, const Dial& d, const RadialAxis& axis, const std::vector<const PlotBrdf*>& brdfs,
               const std::vector<std::vector<Point>>& curves, const std::string& clip) {
  svg.defineClipRect(clip, d.cx - kRadius * 1.06, d.cy - kRadius * 1.06, 2.12 * kRadius, kRadius * 1.06);
  for (size_t b = brdfs.size(); b-- > 0;) {
    std::vector<Point> run;
    auto flush = [&] {
      svg.polyline(run, brdfs[b]->style().colour, brdfs[b]->style().width, brdfs[b]->style().dash, clip);
      run.clear();
    };
    for (const Point& p : curves[b]) {
      const double r = axis.radius(p.y);
      if (!std::isfinite(r)) {
        flush();
        continue;
      }
      run.push_back(d.at(p.x, r));
    }
    flush();
  }
}

}  // namespace

PlotFigure polarFigure(const PlotSet& set, RadialScale scale) {
  const auto brdfs = set.present();
  const Lobes lobes = sampleLobes(set, brdfs);
  // Down to the lowest curve's floor (ρ cos θ_i falls to 0 at the horizon: curveFloor leaves those points out).
  const auto [lo, hi] = decadeRange(lowestFloor(lobes.curves), lobes.peak, 3, set.decades);
  const RadialAxis axis{scale, lo, hi, niceCeil(lobes.peak)};

  GridLayout g;
  g.columns = 2;
  g.rows = 2;
  g.panelW = 2.0 * kRadius;
  g.panelH = kRadius;
  g.left = 40.0;
  g.top = 100.0;
  g.hgap = 95.0;
  g.vgap = 100.0;
  g.bottomAxis = 48.0;
  const std::string radial = scale == RadialScale::Log
                                 ? "log scale from " + set.decadesText(lo, hi, "down to the lowest curve's floor") + " (centre to outer ring)"
                                 : "linear scale, 0 (centre) to " + formatted("%g", axis.linearTop) + " (outer ring)";
  const std::vector<std::string> caption = {
      "In-plane lobes: ρ(L, V) cos θi (1/sr) for L in the plane of incidence, at four viewing angles θV; the radius "
      "is ρ cos θi on a " + radial + ". θi is measured from the normal (up), positive on V's side; the dashed grey "
      "line is the mirror direction θi = −θV. Gaps: unmeasured bins of the table. Metric: none (values, not errors).",
      set.fitsLine(), set.sourceLine()};
  const std::string title = "In-plane polar lobes of " + set.material + " (" + channelName(set.channel) + ")";
  SvgDocument svg = gridFigure(g, title, caption);

  for (size_t s = 0; s < std::size(kThetaV); ++s) {
    const Dial d{g.panelX(int(s)) + kRadius, g.panelY(int(s)) + kRadius};
    drawDial(svg, d, axis, kThetaV[s], g.panelY(int(s)));
    drawLobes(svg, d, axis, brdfs, lobes.curves[s], "clip" + std::to_string(s));
  }
  drawLegend(svg, g.legendX(), g.top - 20.0, g.legendW, set.legend());
  drawCaption(svg, 24.0, g.captionY(), g.width() - 48.0, caption);
  return {"polar", "polar", title, caption, svg.str(), lobes.csv.str()};
}

}  // namespace glossy::plot
