// A small SVG document builder for glossy plot's figures: elements appended in drawing order, text
// escaped for XML, coordinates printed to 0.01 px. Figures are plain SVG 1.1 (no scripts, no external
// references) so that any viewer, rsvg-convert and a paper's toolchain read them alike.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace glossy::plot {

// `text` with &, <, >, " and ' escaped, and control characters (which XML 1.0 forbids) replaced by '?'.
std::string xmlEscape(std::string_view text);

struct Point {
  double x, y;
};

enum class Anchor { Start, Middle, End };

struct TextStyle {
  double size = 13.0;
  Anchor anchor = Anchor::Start;
  bool bold = false;
  std::string colour = "#222222";
  double rotate = 0.0;  // degrees about the text's anchor point
};

class SvgDocument {
 public:
  SvgDocument(double width, double height);

  double width() const { return width_; }
  double height() const { return height_; }

  void line(Point a, Point b, std::string_view colour, double strokeWidth, std::string_view dash = {});
  void rect(double x, double y, double w, double h, std::string_view fill, std::string_view stroke = {}, double strokeWidth = 1.0);
  // An open polyline, clipped to the clip path `clipId` when given (defineClipRect).
  void polyline(const std::vector<Point>& points, std::string_view colour, double strokeWidth, std::string_view dash = {},
                std::string_view clipId = {});
  void circle(Point centre, double r, std::string_view stroke, double strokeWidth, std::string_view fill = "none",
              std::string_view dash = {});
  // Text; `superscript` (may be empty) follows raised and smaller, as in 10^k.
  void text(Point at, std::string_view text, const TextStyle& style, std::string_view superscript = {});
  // A rectangular clip path named `id`.
  void defineClipRect(std::string_view id, double x, double y, double w, double h);
  // Opens/closes a group (e.g. a raster of cells with crisp edges); `attributes` is raw XML.
  void beginGroup(std::string_view attributes);
  void endGroup();

  std::string str() const;

 private:
  double width_, height_;
  std::string defs_, body_;
};

// A coordinate as the figures print it.
std::string coord(double v);

}  // namespace glossy::plot
