// Escaping and number formats for the report's pages (html_text.h).
#include "renderer/report/html_text.h"

#include "materials/core/text.h"
#include "renderer/report/site_layout.h"

#include <cmath>

namespace glossy::report {

std::string escapeHtml(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  return out;
}

std::string styleColour(const std::string& colour) {
  return colour.empty() ? std::string() : " style=\"--model-colour:" + colour + "\"";
}

std::string shortNumber(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return "–";
  return formatted("%.3g", *v);
}

std::string sortValue(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return "";
  return formatted("%.9g", *v);
}

std::string pageStart(const std::string& title, const std::string& root) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"" + std::string(layout::kGenerator) + "\">\n"
         "<title>" + escapeHtml(title) + "</title>\n<link rel=\"icon\" href=\"data:,\">\n"
         "<link rel=\"stylesheet\" href=\"" + root + layout::kStyle + "\">\n"
         "<script src=\"" + root + layout::kScript + "\" defer></script>\n</head>\n<body>\n";
}

std::string pageEnd(const std::string& footerHtml) {
  return "<footer class=\"site\"><p>" + footerHtml + "</p></footer>\n</body>\n</html>\n";
}

}  // namespace glossy::report
