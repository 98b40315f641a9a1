// The summary's markdown subset as HTML (markdown.h).
#include "renderer/report/markdown.h"

#include "renderer/report/html_text.h"

#include <algorithm>
#include <cctype>
#include <sstream>
#include <vector>

namespace glossy::report {

namespace {

std::string_view trimmed(std::string_view s) {
  const size_t begin = s.find_first_not_of(" \t");
  if (begin == std::string_view::npos) return {};
  return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

// Inline markup: `code` first (nothing inside it is markup), then backslash escapes, **strong** and *em* /
// _em_ in the text between code spans. An opener without its closer is text.
std::string emphasis(std::string_view text) {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    // A backslash before punctuation is that character as text, as in CommonMark: "r\\*" is r*, never
    // the start of emphasis.
    if (text[i] == '\\' && i + 1 < text.size() && std::ispunct(static_cast<unsigned char>(text[i + 1]))) {
      out += escapeHtml(text.substr(i + 1, 1));
      i += 2;
      continue;
    }
    const bool strong = text.compare(i, 2, "**") == 0;
    const char mark = text[i];
    if (strong || mark == '*' || mark == '_') {
      const std::string_view closer = strong ? "**" : std::string_view(&text[i], 1);
      const size_t start = i + closer.size();
      const size_t end = text.find(closer, start);
      // Emphasis needs text inside, not starting with a space: "2 * 3 * 4" stays arithmetic.
      if (end != std::string_view::npos && end > start && text[start] != ' ' && text[end - 1] != ' ' &&
          !(mark == '_' && i > 0 && std::isalnum(static_cast<unsigned char>(text[i - 1])))) {
        const char* tag = strong ? "strong" : "em";
        out += std::string("<") + tag + ">" + emphasis(text.substr(start, end - start)) + "</" + tag + ">";
        i = end + closer.size();
        continue;
      }
    }
    const size_t next = std::min(text.find_first_of("*_\\", i + 1), text.size());
    out += escapeHtml(text.substr(i, next - i));
    i = next;
  }
  return out;
}

std::string inlineHtml(std::string_view text) {
  std::string out;
  size_t i = 0;
  while (i < text.size()) {
    const size_t open = text.find('`', i);
    const size_t close = open == std::string_view::npos ? open : text.find('`', open + 1);
    if (close == std::string_view::npos) {
      out += emphasis(text.substr(i));
      break;
    }
    out += emphasis(text.substr(i, open - i)) + "<code>" + escapeHtml(text.substr(open + 1, close - open - 1)) + "</code>";
    i = close + 1;
  }
  return out;
}

// A table row's cells: "| a | b |" or "a | b".
std::vector<std::string_view> cells(std::string_view line) {
  line = trimmed(line);
  if (line.starts_with('|')) line.remove_prefix(1);
  if (line.ends_with('|')) line.remove_suffix(1);
  std::vector<std::string_view> out;
  for (size_t start = 0;;) {
    const size_t bar = std::min(line.find('|', start), line.size());
    out.push_back(trimmed(line.substr(start, bar - start)));
    if (bar == line.size()) return out;
    start = bar + 1;
  }
}

bool isDelimiterRow(std::string_view line) {
  if (line.find('|') == std::string_view::npos || line.find('-') == std::string_view::npos) return false;
  for (std::string_view c : cells(line))
    if (c.empty() || c.find_first_not_of(":-") != std::string_view::npos) return false;
  return true;
}

// The list item a line starts, its text; nullopt-like empty view and `ordered` untouched when it starts none.
bool listItem(std::string_view line, bool& ordered, std::string_view& text) {
  const std::string_view t = trimmed(line);
  if ((t.starts_with("- ") || t.starts_with("* ")) && t.size() > 2) {
    ordered = false;
    text = t.substr(2);
    return true;
  }
  const size_t digits = t.find_first_not_of("0123456789");
  if (digits > 0 && digits != std::string_view::npos && digits <= 9 && t.compare(digits, 2, ". ") == 0) {
    ordered = true;
    text = t.substr(digits + 2);
    return true;
  }
  return false;
}

int headingLevel(std::string_view line) {
  const size_t hashes = line.find_first_not_of('#');
  if (hashes == 0 || hashes > 6 || hashes == std::string_view::npos || line[hashes] != ' ') return 0;
  return int(hashes);
}

}  // namespace

std::string markdownToHtml(std::string_view markdown) {
  std::vector<std::string_view> lines;
  for (size_t start = 0; start <= markdown.size();) {
    size_t end = markdown.find('\n', start);
    if (end == std::string_view::npos) end = markdown.size();
    std::string_view line = markdown.substr(start, end - start);
    if (line.ends_with('\r')) line.remove_suffix(1);
    lines.push_back(line);
    start = end + 1;
  }
  std::ostringstream h;
  size_t i = 0;
  const auto blank = [&](size_t k) { return trimmed(lines[k]).empty(); };
  while (i < lines.size()) {
    const std::string_view line = lines[i];
    bool ordered = false;
    std::string_view item;
    if (blank(i)) {
      ++i;
    } else if (trimmed(line).starts_with("```")) {
      h << "<pre class=\"study-summary\"><code>";
      for (++i; i < lines.size() && !trimmed(lines[i]).starts_with("```"); ++i) h << escapeHtml(lines[i]) << "\n";
      h << "</code></pre>\n";
      ++i;  // the closing fence (or the end)
    } else if (const int level = headingLevel(line); level > 0) {
      const int tag = std::min(6, level + 2);
      h << "<h" << tag << ">" << inlineHtml(trimmed(line.substr(size_t(level)))) << "</h" << tag << ">\n";
      ++i;
    } else if (i + 1 < lines.size() && line.find('|') != std::string_view::npos && isDelimiterRow(lines[i + 1])) {
      const size_t columns = cells(line).size();
      h << "<div class=\"table-wrap\"><table class=\"summary-table\">\n<thead><tr>";
      for (std::string_view c : cells(line)) h << "<th scope=\"col\">" << inlineHtml(c) << "</th>";
      h << "</tr></thead>\n<tbody>\n";
      for (i += 2; i < lines.size() && !blank(i) && lines[i].find('|') != std::string_view::npos; ++i) {
        std::vector<std::string_view> row = cells(lines[i]);
        row.resize(columns);  // GitHub's rule: missing cells are empty, extra ones are dropped
        h << "<tr>";
        for (std::string_view c : row) h << "<td>" << inlineHtml(c) << "</td>";
        h << "</tr>\n";
      }
      h << "</tbody>\n</table></div>\n";
    } else if (listItem(line, ordered, item)) {
      const char* tag = ordered ? "ol" : "ul";
      h << "<" << tag << ">\n";
      bool sameKind = ordered;
      for (; i < lines.size() && listItem(lines[i], sameKind, item) && sameKind == ordered; ++i)
        h << "<li>" << inlineHtml(item) << "</li>\n";
      h << "</" << tag << ">\n";
    } else {
      // A paragraph: lines up to a blank line or the start of another block.
      std::string text;
      for (; i < lines.size() && !blank(i); ++i) {
        bool o = false;
        std::string_view it;
        if (!text.empty() && (headingLevel(lines[i]) > 0 || trimmed(lines[i]).starts_with("```") || listItem(lines[i], o, it))) break;
        if (!text.empty()) text += '\n';
        text += trimmed(lines[i]);
      }
      h << "<p>" << inlineHtml(text) << "</p>\n";
    }
  }
  return h.str();
}

}  // namespace glossy::report
