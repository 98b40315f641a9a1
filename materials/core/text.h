// Numbers in text. Read (imported parameters, command-line options, stdin): what std::from_chars reads
// (decimal or scientific, "inf", "nan"), with an optional leading '+', and nothing else around it.
// Written: printf's formats, into a std::string (GCC 12 has no std::format).
#pragma once

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glossy {

template <class... T>
std::string formatted(const char* format, T... values) {
  std::string s(size_t(std::max(0, std::snprintf(nullptr, 0, format, values...))), '\0');
  std::snprintf(s.data(), s.size() + 1, format, values...);
  return s;
}

// `text` as one printable line of about `maxLength` bytes at most ("..." marks a cut): line breaks become
// "; ", control characters and bytes that are not well-formed UTF-8 become '?', so a parser's message
// quoting a binary file stays one readable line while names in any language pass.
std::string printableLine(const std::string& text, size_t maxLength = 300);

// `text` as one CSV field (RFC 4180): quoted, with its quotes doubled, when it holds a comma, a quote or a
// line break.
inline std::string csvField(std::string_view text) {
  if (text.find_first_of(",\"\n\r") == std::string_view::npos) return std::string(text);
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// The items' text — text(item), the item itself by default — joined by `separator`: "a, b, c".
template <class Items, class Text = std::identity>
std::string joined(const Items& items, std::string_view separator, Text text = {}) {
  std::string out;
  bool first = true;  // not out.empty(): an empty first item still takes a separator after it
  for (const auto& item : items) {
    out.append(first ? "" : separator).append(std::string_view(text(item)));
    first = false;
  }
  return out;
}

// `text` as a message's one safe line, the form every message takes before it reaches a terminal or
// Python (InputError, notes, the command line's errors): control characters, line breaks, bytes that are
// not well-formed UTF-8 and the Unicode characters that reorder or break a line are escaped ("\n", "\x1b",
// "\u202e"), so a file name or a file's content cannot move the cursor, forge a second line or hide
// part of the message; a message of more than `maxCharacters` characters keeps its start and its end around
// "… (N characters) …", so the file it names and the problem it states both stay.
std::string safeLine(std::string_view text, size_t maxCharacters = 1000);

// `text` echoed in a message: at most `maxCharacters` characters, then "… (5,012 characters)", so a 309-digit
// number or a pasted file does not fill the screen. (safeLine escapes it with the rest of the message.)
std::string shortened(std::string_view text, size_t maxCharacters = 40);

// A source or scene as a published site shows it: every word that is a path cut to its file name
// ("MERL /home/me/merl/chrome.binary" -> "MERL chrome.binary"), so the site carries no local folders and
// two checkouts of one scene read alike.
std::string withoutFolders(const std::string& text);

inline std::optional<double> parseNumber(std::string_view text) {
  if (text.starts_with('+')) text.remove_prefix(1);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

// "x, y,z": comma-separated numbers, each with optional spaces or tabs around it; nullopt if any is not one.
inline std::optional<std::vector<double>> parseNumberList(std::string_view text) {
  std::vector<double> values;
  for (size_t start = 0;;) {
    const size_t comma = std::min(text.find(',', start), text.size());
    std::string_view item = text.substr(start, comma - start);
    item.remove_prefix(std::min(item.find_first_not_of(" \t"), item.size()));
    item.remove_suffix(item.size() - (item.find_last_not_of(" \t") + 1));
    const auto v = parseNumber(item);
    if (!v) return std::nullopt;
    values.push_back(*v);
    if (comma == text.size()) return values;
    start = comma + 1;
  }
}

}  // namespace glossy
