// One figure of glossy plot: its kind (the plots.json vocabulary), file stem, title and caption, the SVG
// and the CSV of the numbers behind it; and the layout the figures share: a grid of plot areas, the legend
// to their right (where it cannot hide a curve), the caption underneath.
#pragma once

#include "renderer/plot/chart.h"
#include "renderer/plot/svg_document.h"

#include <string>
#include <vector>

namespace glossy::plot {

struct PlotFigure {
  std::string kind;  // "theta_h" | "image_slice" | "albedo" | "polar"
  std::string name;  // file stem: NAME.svg, NAME.png, NAME.csv
  std::string title;
  std::vector<std::string> caption;  // paragraphs; plots.json joins them with a space
  std::string svg, csv;
};

struct GridLayout {
  int columns = 1, rows = 1;
  double panelW = 330.0, panelH = 230.0;
  double legendW = 190.0;
  double left = 90.0, top = 78.0, hgap = 105.0, vgap = 92.0, right = 24.0;
  double bottomAxis = 52.0;  // tick labels and axis label under the last row

  double panelX(int i) const { return left + (i % columns) * (panelW + hgap); }
  double panelY(int i) const { return top + (i / columns) * (panelH + vgap); }
  double legendX() const { return left + columns * panelW + (columns - 1) * hgap + 34.0; }
  double width() const { return legendX() + legendW + right; }
  double captionY() const { return top + rows * panelH + (rows - 1) * vgap + bottomAxis + 10.0; }
};

// The figure's title at the top left, in bold.
void drawFigureTitle(SvgDocument& svg, const std::string& title);
// A figure laid out by `g`: as wide as the grid and its legend, as tall as its caption needs, titled.
SvgDocument gridFigure(const GridLayout& g, const std::string& title, const std::vector<std::string>& caption);

}  // namespace glossy::plot
