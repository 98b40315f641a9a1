#include "materials/core/text.h"

#include <filesystem>
#include <sstream>

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

// The Unicode characters that break a line or reorder what follows it (bidirectional overrides and
// isolates): a terminal shows them as if they were not there.
bool isInvisibleControl(char32_t c) {
  return (c >= 0x80 && c <= 0x9F) || c == 0x2028 || c == 0x2029 || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069) ||
         c == 0x200E || c == 0x200F || c == 0x061C || c == 0xFEFF;
}

char32_t codePoint(std::string_view s) {
  const auto b = [&](size_t k) { return char32_t(static_cast<unsigned char>(s[k])); };
  if (s.size() == 2) return ((b(0) & 0x1F) << 6) | (b(1) & 0x3F);
  if (s.size() == 3) return ((b(0) & 0x0F) << 12) | ((b(1) & 0x3F) << 6) | (b(2) & 0x3F);
  return ((b(0) & 0x07) << 18) | ((b(1) & 0x3F) << 12) | ((b(2) & 0x3F) << 6) | (b(3) & 0x3F);
}

// "5012" as "5,012".
// Built by appending: GCC 12 misreads string::insert's overlap check here and warns (-Wrestrict).
std::string withThousands(size_t n) {
  const std::string digits = std::to_string(n);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// `text` as its characters, each escaped when it is not printable (see safeLine).
std::vector<std::string> safeCharacters(std::string_view text) {
  const std::string s(text);
  std::vector<std::string> out;
  out.reserve(text.size());
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x80) {
      const size_t n = utf8Length(s, i);
      if (n == 0) {
        out.push_back(formatted("\\x%02x", unsigned(c)));
      } else {
        const std::string_view ch = text.substr(i, n);
        const char32_t cp = codePoint(ch);
        out.push_back(isInvisibleControl(cp) ? formatted("\\u%04x", unsigned(cp)) : std::string(ch));
        i += n - 1;
      }
    } else if (c == '\n') {
      out.push_back("\\n");
    } else if (c == '\r') {
      out.push_back("\\r");
    } else if (c == '\t') {
      out.push_back("\\t");
    } else if (c < 0x20 || c == 0x7f) {
      out.push_back(formatted("\\x%02x", unsigned(c)));
    } else {
      out.push_back(std::string(1, char(c)));
    }
  }
  return out;
}

// The number of characters (code points; a stray byte counts as one) of `text`.
size_t characterCount(std::string_view text) {
  const std::string s(text);
  size_t count = 0;
  for (size_t i = 0; i < s.size(); ++count) {
    const size_t n = static_cast<unsigned char>(s[i]) >= 0x80 ? utf8Length(s, i) : 1;
    i += n == 0 ? 1 : n;
  }
  return count;
}

}  // namespace

std::string safeLine(std::string_view text, size_t maxCharacters) {
  const std::vector<std::string> chars = safeCharacters(text);
  if (chars.size() <= maxCharacters) return joined(chars, "");
  // Start and end: what is named comes first in a message, what is wrong with it last.
  const size_t tail = maxCharacters / 3, head = maxCharacters - tail;
  std::string out;
  for (size_t k = 0; k < head; ++k) out += chars[k];
  out += "… (" + withThousands(chars.size()) + " characters) …";
  for (size_t k = chars.size() - tail; k < chars.size(); ++k) out += chars[k];
  return out;
}

std::string shortened(std::string_view text, size_t maxCharacters) {
  const size_t count = characterCount(text);
  if (count <= maxCharacters) return std::string(text);
  const std::string s(text);
  size_t end = 0;
  for (size_t k = 0; k < maxCharacters; ++k) {
    const size_t n = static_cast<unsigned char>(s[end]) >= 0x80 ? utf8Length(s, end) : 1;
    end += n == 0 ? 1 : n;
  }
  return s.substr(0, end) + "… (" + withThousands(count) + " characters)";
}

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

std::string withoutFolders(const std::string& text) {
  std::istringstream in(text);
  std::string word, out;
  while (in >> word) {
    if (word.find('/') != std::string::npos)
      if (const std::string file = std::filesystem::path(word).filename().string(); !file.empty()) word = file;
    out += (out.empty() ? "" : " ") + word;
  }
  return out;
}

}  // namespace glossy
