#include "materials/core/text.h"

namespace glossy {

namespace {

// The length of the well-formed UTF-8 sequence starting at text[i], or 0.
size_t utf8Length(const std::string& text, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  const size_t n = c >= 0xC2 && c <= 0xDF ? 2 : c >= 0xE0 && c <= 0xEF ? 3 : c >= 0xF0 && c <= 0xF4 ? 4 : 0;
  if (n == 0 || i + n > text.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  return n;
}

}  // namespace

std::string printableLine(const std::string& text, size_t maxLength) {
  std::string out;
  size_t i = 0;
  for (; i < text.size() && out.size() < maxLength; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      if (i + 1 < text.size()) out += "; ";
    } else if (c == '\r') {
      continue;
    } else if (c >= 0x80) {
      // Names may be any language: whole UTF-8 characters pass, stray bytes of a binary file do not.
      const size_t n = utf8Length(text, i);
      if (n == 0) {
        out += '?';
      } else {
        out.append(text, i, n);
        i += n - 1;
      }
    } else {
      out += c >= 0x20 && c < 0x7f ? char(c) : '?';
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  if (i < text.size()) out += "...";
  return out;
}

}  // namespace glossy
