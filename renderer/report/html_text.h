// Text into HTML: every string that came from a file (material names, notes, parameters, captions) goes
// through escapeHtml, in element content and in quoted attributes alike; numbers are written by the two
// formats the site uses — short for people, full precision for sorting; and the head and foot every page
// shares.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace glossy::report {

// &, <, >, " and ' as character references.
std::string escapeHtml(std::string_view text);

// ' style="--model-colour:COLOUR"', the attribute that colours a model's cell or button; "" without a colour.
std::string styleColour(const std::string& colour);

// Three significant digits, or "–" when absent.
std::string shortNumber(const std::optional<double>& v);
// Full precision for data-value attributes; "" when absent (sorted last).
std::string sortValue(const std::optional<double>& v);

// The opening of every page up to <body>: its title, the style sheet and script found through `root`
// (the relative path to the site's top, "" or "../../"), and no favicon request (an empty data: icon).
std::string pageStart(const std::string& title, const std::string& root);
// The page's footer and closing tags; `footerHtml` is written as is (the caller escapes what it puts in).
std::string pageEnd(const std::string& footerHtml);

}  // namespace glossy::report
