// The parts every glossy plot figure is drawn from: axes on linear, log10 or square-root scales with their
// ticks, grid lines and labels; curves in data units, broken where a value is missing; the legend beside
// (never over) the plot areas; and the caption under them. Log axes label their decades 10^k.
#pragma once

#include "renderer/plot/svg_document.h"

#include <functional>
#include <string>
#include <vector>

namespace glossy::plot {

enum class Scale {
  Linear,
  Log10,
  Sqrt,  // position ∝ √v: MERL's θ_h binning, which gives the narrow peak at θ_h = 0 room beside the tail
};

struct Tick {
  double value;
  std::string label, superscript;  // "10" and "-2" for 10^-2; empty label: an unlabelled minor tick
};

struct Axis {
  Scale scale = Scale::Linear;
  double lo = 0.0, hi = 1.0;
  std::string label;
  std::vector<Tick> ticks;
  // Where v falls on the axis, 0 at lo and 1 at hi; NaN for a value a log axis cannot show (≤ 0, NaN).
  double fraction(double v) const;
};

// Ticks every `step` from lo to hi, labelled with `decimals` decimals.
Axis linearAxis(double lo, double hi, double step, int decimals, std::string label);
// Decades 10^lo … 10^hi, each labelled; unlabelled minor ticks at 2…9 × 10^k when there are at most 6 decades.
Axis logAxis(int decadeLo, int decadeHi, std::string label);
// 0 … 90 (degrees) on a square-root scale, ticks where the eye wants them (0, 1, 5, 10, 20, 30, 45, 60, 90).
Axis sqrtDegreesAxis(std::string label);

// The widest a log axis that follows its data gets: beyond it a value is a curve falling to zero, not a floor.
constexpr int kMaxDecades = 12;
// The decades [lo, hi] of a log axis for positive values up to `peak`: hi the decade at or above the peak;
// with `decades` > 0 exactly that many below it (glossy plot --decades), else down to the decade at or
// below `floor`, so that every curve's floor shows, at least `minDecades` and at most kMaxDecades wide.
std::pair<int, int> decadeRange(double floor, double peak, int minDecades, int decades = 0);
// A curve's floor: the 2nd percentile of its positive values, so that the last few points where a curve
// falls toward zero (at the horizon) do not stretch the axis over decades no curve lies in. +Inf when
// there are none.
double curveFloor(const std::vector<double>& values);
// The lowest floor of the y values of every curve, curves[group][curve]: where a log axis over them all must
// reach for each curve's floor to show.
double lowestFloor(const std::vector<std::vector<std::vector<Point>>>& curves);
// The top of a linear axis for values up to `v`: the smallest of 1, 2, 2.5, 5 × 10^k at least v (1 for v ≤ 0).
double niceCeil(double v);

struct PlotArea {
  double x, y, w, h;  // in the document, y down
  Axis xAxis, yAxis;
  bool grid = true;  // grid lines under the curves (not under an image)
  Point at(double xv, double yv) const;  // document position of a data point (NaN coordinates if not showable)
  // Grid lines, frame, tick marks and labels, axis labels, and the title over the area; `clipId` names a clip
  // path to the area that curves use.
  void draw(SvgDocument& svg, const std::string& title, const std::string& clipId) const;
};

struct CurveStyle {
  std::string colour = "#000000";
  double width = 1.6;
  std::string dash;  // SVG dasharray; empty: solid
};

// A vertical colour bar at (x, y), w × h: colourAt(t) for t from 0 (bottom) to 1 (top), ticks (t in [0, 1],
// label, superscript) on its right, and `label` beside them.
void drawColourBar(SvgDocument& svg, double x, double y, double w, double h, const std::function<std::string(double)>& colourAt,
                   const std::vector<std::pair<double, Tick>>& ticks, const std::string& label);

// The curve through data points (x, y), in order; a point the axes cannot show (NaN, or ≤ 0 on a log axis)
// breaks the curve rather than being drawn as 0.
void drawCurve(SvgDocument& svg, const PlotArea& area, const std::vector<Point>& data, const CurveStyle& style,
               const std::string& clipId);

struct LegendEntry {
  std::string label;
  CurveStyle style;
  bool present = true;
  std::string note;  // under the label, e.g. "not in the file" (grey)
};
// The legend in a box at (x, y), `width` wide; returns its height.
double drawLegend(SvgDocument& svg, double x, double y, double width, const std::vector<LegendEntry>& entries);

// `text` broken into lines of at most about `width` px at `fontSize` (DejaVu Sans' mean advance).
std::vector<std::string> wrapText(const std::string& text, double width, double fontSize);
// Caption lines from y down; returns the height used.
double drawCaption(SvgDocument& svg, double x, double y, double width, const std::vector<std::string>& paragraphs);
// The height drawCaption will use.
double captionHeight(double width, const std::vector<std::string>& paragraphs);

}  // namespace glossy::plot
