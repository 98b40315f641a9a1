#include "renderer/plot/svg_document.h"

#include "materials/core/text.h"

#include <cctype>
#include <cmath>

namespace glossy::plot {

std::string xmlEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += (static_cast<unsigned char>(c) < 0x20 && c != '\t') ? '?' : c;
    }
  }
  return out;
}

std::string coord(double v) {
  if (!std::isfinite(v)) v = 0.0;  // never reaches a figure: callers clip first; this keeps the XML valid
  std::string s = formatted("%.2f", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

namespace {

std::string dashAttribute(std::string_view dash) {
  return dash.empty() ? "" : " stroke-dasharray=\"" + std::string(dash) + "\"";
}

// The figures' angle names, θh, θd, φd, θi, θV, θL, ωL: Greek letter, then one of h d i V L not followed by a
// letter, set with the second character as a subscript (lowered with dy and restored by the next run, which
// every SVG renderer follows).
std::string withSubscripts(std::string_view text, double size) {
  static const std::string_view greek[] = {"θ", "φ", "ω"};
  const std::string down = coord(0.28 * size), up = coord(-0.28 * size), small = coord(0.75 * size);
  std::string out, run;
  bool lowered = false;
  auto flushRun = [&] {
    if (run.empty()) return;
    out += lowered ? "<tspan dy=\"" + up + "\">" + xmlEscape(run) + "</tspan>" : xmlEscape(run);
    lowered = false;
    run.clear();
  };
  for (size_t i = 0; i < text.size();) {
    bool matched = false;
    for (std::string_view g : greek) {
      if (text.substr(i, g.size()) != g || i + g.size() >= text.size()) continue;
      const char sub = text[i + g.size()];
      const char after = i + g.size() + 1 < text.size() ? text[i + g.size() + 1] : ' ';
      if (std::string_view("hdiVL").find(sub) == std::string_view::npos || std::isalpha(static_cast<unsigned char>(after))) continue;
      run += g;
      flushRun();
      out += "<tspan dy=\"" + down + "\" font-size=\"" + small + "\">" + std::string(1, sub) + "</tspan>";
      lowered = true;
      i += g.size() + 1;
      matched = true;
      break;
    }
    if (!matched) run += text[i++];
  }
  if (!run.empty()) flushRun();
  return out;
}

}  // namespace

SvgDocument::SvgDocument(double width, double height) : width_(width), height_(height) {}

void SvgDocument::line(Point a, Point b, std::string_view colour, double w, std::string_view dash) {
  body_ += "<line x1=\"" + coord(a.x) + "\" y1=\"" + coord(a.y) + "\" x2=\"" + coord(b.x) + "\" y2=\"" + coord(b.y) +
           "\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" + coord(w) + "\"" + dashAttribute(dash) + "/>\n";
}

void SvgDocument::rect(double x, double y, double w, double h, std::string_view fill, std::string_view stroke, double sw) {
  body_ += "<rect x=\"" + coord(x) + "\" y=\"" + coord(y) + "\" width=\"" + coord(w) + "\" height=\"" + coord(h) +
           "\" fill=\"" + std::string(fill) + "\"";
  if (!stroke.empty()) body_ += " stroke=\"" + std::string(stroke) + "\" stroke-width=\"" + coord(sw) + "\"";
  body_ += "/>\n";
}

void SvgDocument::polyline(const std::vector<Point>& points, std::string_view colour, double w, std::string_view dash,
                           std::string_view clipId) {
  if (points.size() < 2) return;
  std::string p;
  p.reserve(points.size() * 14);
  for (const Point& q : points) p += coord(q.x) + "," + coord(q.y) + " ";
  p.pop_back();
  body_ += "<polyline points=\"" + p + "\" fill=\"none\" stroke=\"" + std::string(colour) + "\" stroke-width=\"" + coord(w) +
           "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"" + dashAttribute(dash);
  if (!clipId.empty()) body_ += " clip-path=\"url(#" + std::string(clipId) + ")\"";
  body_ += "/>\n";
}

void SvgDocument::circle(Point c, double r, std::string_view stroke, double w, std::string_view fill, std::string_view dash) {
  body_ += "<circle cx=\"" + coord(c.x) + "\" cy=\"" + coord(c.y) + "\" r=\"" + coord(r) + "\" fill=\"" + std::string(fill) +
           "\" stroke=\"" + std::string(stroke) + "\" stroke-width=\"" + coord(w) + "\"" + dashAttribute(dash) + "/>\n";
}

void SvgDocument::text(Point at, std::string_view text, const TextStyle& s, std::string_view superscript) {
  static const char* anchors[] = {"start", "middle", "end"};
  body_ += "<text x=\"" + coord(at.x) + "\" y=\"" + coord(at.y) + "\" font-size=\"" + coord(s.size) + "\" text-anchor=\"" +
           anchors[int(s.anchor)] + "\" fill=\"" + s.colour + "\"";
  if (s.bold) body_ += " font-weight=\"bold\"";
  if (s.rotate != 0.0) body_ += " transform=\"rotate(" + coord(s.rotate) + " " + coord(at.x) + " " + coord(at.y) + ")\"";
  // Spaces next to a subscript's runs are kept only when preserved (renderers trim them at a tspan's edge).
  const std::string content = withSubscripts(text, s.size);
  if (content.find("<tspan") != std::string::npos) body_ += " xml:space=\"preserve\"";
  body_ += '>';
  body_ += content;
  // Raised with dy rather than baseline-shift, which not every renderer honours.
  if (!superscript.empty())
    body_ += "<tspan dy=\"" + coord(-0.45 * s.size) + "\" font-size=\"" + coord(0.72 * s.size) + "\">" + xmlEscape(superscript) +
             "</tspan>";
  body_ += "</text>\n";
}

void SvgDocument::defineClipRect(std::string_view id, double x, double y, double w, double h) {
  defs_ += "<clipPath id=\"" + std::string(id) + "\"><rect x=\"" + coord(x) + "\" y=\"" + coord(y) + "\" width=\"" + coord(w) +
           "\" height=\"" + coord(h) + "\"/></clipPath>\n";
}

void SvgDocument::beginGroup(std::string_view attributes) { body_ += "<g " + std::string(attributes) + ">\n"; }
void SvgDocument::endGroup() { body_ += "</g>\n"; }

std::string SvgDocument::str() const {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" +
         coord(width_) + "\" height=\"" + coord(height_) + "\" viewBox=\"0 0 " + coord(width_) + " " + coord(height_) +
         "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n<defs>\n" + defs_ + "</defs>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n" +
         body_ + "</svg>\n";
}

}  // namespace glossy::plot
