// A study's summary (analysis/summary.md) as HTML, for the report's study page. A small, well-defined
// subset of CommonMark and GitHub's tables, the markdown glossy itself writes: ATX headings (# to ######,
// shown two levels down, under the page's own h1 and h2), paragraphs, lists (- or * bullets, "1." numbers,
// one level), pipe tables (a header row, a |---| delimiter row, body rows), fenced code blocks (```), and
// inline `code`, **strong** and *emphasis* (or _emphasis_), and backslash escapes of punctuation (r\* is
// r*). Everything else is text: every character of the
// input reaches the page through escapeHtml, so raw HTML, links and images in a summary show as what they
// are, never as markup.
#pragma once

#include <string>
#include <string_view>

namespace glossy::report {

std::string markdownToHtml(std::string_view markdown);

}  // namespace glossy::report
