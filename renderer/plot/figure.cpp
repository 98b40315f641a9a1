#include "renderer/plot/figure.h"

namespace glossy::plot {

void drawFigureTitle(SvgDocument& svg, const std::string& title) {
  svg.text({24.0, 32.0}, title, {17.0, Anchor::Start, true, "#111111"});
}

SvgDocument gridFigure(const GridLayout& g, const std::string& title, const std::vector<std::string>& caption) {
  const double width = g.width();
  SvgDocument svg(width, g.captionY() + captionHeight(width - 48.0, caption) + 16.0);
  drawFigureTitle(svg, title);
  return svg;
}

}  // namespace glossy::plot
