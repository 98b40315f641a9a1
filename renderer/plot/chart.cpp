#include "renderer/plot/chart.h"

#include "materials/core/text.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glossy::plot {

namespace {

constexpr double kTickFont = 12.0, kLabelFont = 13.5, kTitleFont = 14.0, kCaptionFont = 12.0;
constexpr const char* kGrid = "#e3e3e3";
constexpr const char* kMinorGrid = "#f2f2f2";
constexpr const char* kFrame = "#444444";

double mapped(Scale s, double v) {
  switch (s) {
    case Scale::Log10: return v > 0.0 ? std::log10(v) : std::nan("");
    case Scale::Sqrt: return v >= 0.0 ? std::sqrt(v) : std::nan("");
    default: return v;
  }
}

// Characters of UTF-8 text (continuation bytes do not advance).
size_t characters(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

// Advance of DejaVu Sans at 1 px, averaged over mixed text: enough to wrap captions without measuring fonts.
constexpr double kMeanAdvance = 0.56;

}  // namespace

double Axis::fraction(double v) const {
  const double a = mapped(scale, lo), b = mapped(scale, hi), m = mapped(scale, v);
  if (!std::isfinite(m)) return std::nan("");
  return (m - a) / (b - a);
}

Axis linearAxis(double lo, double hi, double step, int decimals, std::string label) {
  Axis a{Scale::Linear, lo, hi, std::move(label), {}};
  const int n = int(std::floor((hi - lo) / step + 1e-9));
  for (int i = 0; i <= n; ++i) {
    const double v = lo + i * step;
    a.ticks.push_back({v, formatted("%.*f", decimals, std::abs(v) < 1e-12 ? 0.0 : v), ""});
  }
  return a;
}

Axis logAxis(int decadeLo, int decadeHi, std::string label) {
  Axis a{Scale::Log10, std::pow(10.0, decadeLo), std::pow(10.0, decadeHi), std::move(label), {}};
  const bool minor = decadeHi - decadeLo <= 6;
  for (int k = decadeLo; k <= decadeHi; ++k) {
    a.ticks.push_back({std::pow(10.0, k), "10", std::to_string(k)});
    if (minor && k < decadeHi)
      for (int m = 2; m <= 9; ++m) a.ticks.push_back({m * std::pow(10.0, k), "", ""});
  }
  return a;
}

Axis sqrtDegreesAxis(std::string label) {
  Axis a{Scale::Sqrt, 0.0, 90.0, std::move(label), {}};
  for (double v : {0.0, 1.0, 5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 90.0}) a.ticks.push_back({v, formatted("%g", v), ""});
  for (double v : {0.25, 2.0, 3.0, 4.0, 15.0, 25.0, 35.0, 40.0, 50.0, 55.0, 70.0, 80.0}) a.ticks.push_back({v, "", ""});
  return a;
}

double niceCeil(double v) {
  if (!(v > 0.0) || !std::isfinite(v)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * p >= v * (1.0 - 1e-12)) return m * p;
  return 10.0 * p;
}

std::pair<int, int> decadeRange(double floor, double peak, int minDecades, int decades) {
  if (!(peak > 0.0) || !std::isfinite(peak)) return {-1, 0};
  const int hi = int(std::ceil(std::log10(peak) - 1e-9));
  if (decades > 0) return {hi - decades, hi};
  int lo = floor > 0.0 && std::isfinite(floor) ? int(std::floor(std::log10(floor) + 1e-9)) : hi - minDecades;
  lo = std::clamp(lo, hi - std::max(minDecades, kMaxDecades), hi - minDecades);
  return {lo, hi};
}

double curveFloor(const std::vector<double>& values) {
  std::vector<double> positive;
  for (double v : values)
    if (v > 0.0 && std::isfinite(v)) positive.push_back(v);
  if (positive.empty()) return std::numeric_limits<double>::infinity();
  const auto nth = positive.begin() + std::ptrdiff_t(positive.size() / 50);
  std::nth_element(positive.begin(), nth, positive.end());
  return *nth;
}

double lowestFloor(const std::vector<std::vector<std::vector<Point>>>& curves) {
  double floor = std::numeric_limits<double>::infinity();
  for (const auto& group : curves)
    for (const auto& curve : group) {
      std::vector<double> ys;
      for (const Point& p : curve) ys.push_back(p.y);
      floor = std::min(floor, curveFloor(ys));
    }
  return floor;
}

Point PlotArea::at(double xv, double yv) const {
  return {x + w * xAxis.fraction(xv), y + h * (1.0 - yAxis.fraction(yv))};
}

void PlotArea::draw(SvgDocument& svg, const std::string& title, const std::string& clipId) const {
  svg.defineClipRect(clipId, x, y, w, h);
  // Grid: minor first, so major lines lie over them.
  for (int pass = 0; pass < (grid ? 2 : 0); ++pass) {
    for (const Tick& t : xAxis.ticks) {
      if (t.label.empty() != (pass == 0)) continue;
      const double px = x + w * xAxis.fraction(t.value);
      if (std::isfinite(px)) svg.line({px, y}, {px, y + h}, pass == 0 ? kMinorGrid : kGrid, 1.0);
    }
    for (const Tick& t : yAxis.ticks) {
      if (t.label.empty() != (pass == 0)) continue;
      const double py = y + h * (1.0 - yAxis.fraction(t.value));
      if (std::isfinite(py)) svg.line({x, py}, {x + w, py}, pass == 0 ? kMinorGrid : kGrid, 1.0);
    }
  }
  svg.rect(x, y, w, h, "none", kFrame, 1.0);
  TextStyle tick{kTickFont, Anchor::Middle};
  for (const Tick& t : xAxis.ticks) {
    const double px = x + w * xAxis.fraction(t.value);
    if (!std::isfinite(px)) continue;
    svg.line({px, y + h}, {px, y + h + (t.label.empty() ? 3.0 : 5.0)}, kFrame, 1.0);
    if (!t.label.empty()) svg.text({px, y + h + 18.0}, t.label, tick, t.superscript);
  }
  tick.anchor = Anchor::End;
  double widest = 0.0;
  for (const Tick& t : yAxis.ticks) {
    const double py = y + h * (1.0 - yAxis.fraction(t.value));
    if (!std::isfinite(py)) continue;
    svg.line({x - (t.label.empty() ? 3.0 : 5.0), py}, {x, py}, kFrame, 1.0);
    if (t.label.empty()) continue;
    // The anchor takes the whole text, superscript included.
    const double sup = characters(t.superscript) * kTickFont * 0.72 * kMeanAdvance;
    svg.text({x - 8.0, py + 4.0}, t.label, tick, t.superscript);
    widest = std::max(widest, characters(t.label) * kTickFont * kMeanAdvance + sup);
  }
  svg.text({x + 0.5 * w, y + h + 38.0}, xAxis.label, {kLabelFont, Anchor::Middle});
  svg.text({x - 16.0 - widest, y + 0.5 * h}, yAxis.label, {kLabelFont, Anchor::Middle, false, "#222222", -90.0});
  if (!title.empty()) svg.text({x + 0.5 * w, y - 9.0}, title, {kTitleFont, Anchor::Middle, true});
}

void drawColourBar(SvgDocument& svg, double x, double y, double w, double h, const std::function<std::string(double)>& colourAt,
                   const std::vector<std::pair<double, Tick>>& ticks, const std::string& label) {
  constexpr int kSteps = 96;
  svg.beginGroup("shape-rendering=\"crispEdges\"");
  for (int i = 0; i < kSteps; ++i) {
    const double t = (i + 0.5) / kSteps;
    svg.rect(x, y + h * (1.0 - double(i + 1) / kSteps), w, h / kSteps + 0.6, colourAt(t));
  }
  svg.endGroup();
  svg.rect(x, y, w, h, "none", kFrame, 1.0);
  double widest = 0.0;
  for (const auto& [t, tick] : ticks) {
    const double py = y + h * (1.0 - t);
    svg.line({x + w, py}, {x + w + 5.0, py}, kFrame, 1.0);
    svg.text({x + w + 8.0, py + 4.0}, tick.label, {kTickFont, Anchor::Start}, tick.superscript);
    widest = std::max(widest, (characters(tick.label) + 0.72 * characters(tick.superscript)) * kTickFont * kMeanAdvance);
  }
  svg.text({x + w + 32.0 + widest, y + 0.5 * h}, label, {kLabelFont, Anchor::Middle, false, "#222222", -90.0});
}

void drawCurve(SvgDocument& svg, const PlotArea& area, const std::vector<Point>& data, const CurveStyle& style,
               const std::string& clipId) {
  std::vector<Point> run;
  auto flush = [&] {
    if (run.size() == 1) run.push_back({run[0].x + 0.5, run[0].y});  // a lone point still shows
    svg.polyline(run, style.colour, style.width, style.dash, clipId);
    run.clear();
  };
  for (const Point& d : data) {
    const Point p = area.at(d.x, d.y);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      flush();
      continue;
    }
    // Far outside the area (a log axis' floor): pin just outside it, so the clip cuts the line cleanly.
    run.push_back({p.x, std::clamp(p.y, area.y - 50.0, area.y + area.h + 50.0)});
  }
  flush();
}

double drawLegend(SvgDocument& svg, double x, double y, double width, const std::vector<LegendEntry>& entries) {
  constexpr double kRow = 20.0, kNoteRow = 15.0, kPad = 8.0;
  double h = kPad;
  for (const LegendEntry& e : entries) h += kRow + (e.note.empty() ? 0.0 : kNoteRow * wrapText(e.note, width - 42.0, 11.0).size());
  h += kPad - 4.0;
  svg.rect(x, y, width, h, "#ffffff", "#bbbbbb", 1.0);
  double cy = y + kPad + 10.0;
  for (const LegendEntry& e : entries) {
    if (e.present) svg.line({x + 8.0, cy - 4.0}, {x + 34.0, cy - 4.0}, e.style.colour, std::max(2.0, e.style.width), e.style.dash);
    else svg.line({x + 8.0, cy - 4.0}, {x + 34.0, cy - 4.0}, "#cccccc", 1.0, "2 3");
    svg.text({x + 40.0, cy}, e.label, {12.5, Anchor::Start, false, e.present ? "#222222" : "#999999"});
    cy += kRow;
    if (!e.note.empty())
      for (const std::string& line : wrapText(e.note, width - 42.0, 11.0)) {
        svg.text({x + 40.0, cy - 5.0}, line, {11.0, Anchor::Start, false, "#777777"});
        cy += kNoteRow;
      }
  }
  return h;
}

std::vector<std::string> wrapText(const std::string& text, double width, double fontSize) {
  const size_t perLine = std::max<size_t>(8, size_t(width / (fontSize * kMeanAdvance)));
  std::vector<std::string> lines;
  std::string line;
  size_t lineChars = 0;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const std::string word = text.substr(start, end - start);
    const size_t n = characters(word);
    if (!line.empty() && lineChars + 1 + n > perLine) {
      lines.push_back(line);
      line.clear();
      lineChars = 0;
    }
    if (!line.empty()) {
      line += ' ';
      ++lineChars;
    }
    line += word;
    lineChars += n;
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

double captionHeight(double width, const std::vector<std::string>& paragraphs) {
  double h = 0.0;
  for (const std::string& p : paragraphs) h += 16.0 * wrapText(p, width, kCaptionFont).size() + 2.0;
  return h;
}

double drawCaption(SvgDocument& svg, double x, double y, double width, const std::vector<std::string>& paragraphs) {
  double cy = y + 12.0;
  for (const std::string& p : paragraphs) {
    for (const std::string& line : wrapText(p, width, kCaptionFont)) {
      svg.text({x, cy}, line, {kCaptionFont, Anchor::Start, false, "#333333"});
      cy += 16.0;
    }
    cy += 2.0;
  }
  return cy - y;
}

}  // namespace glossy::plot
