#include "materials/params/material_name.h"

#include "materials/core/input_error.h"

namespace glossy {

namespace {

bool isAlnum(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

}  // namespace

bool isMaterialName(std::string_view name) {
  if (name.empty() || name.size() > kMaxMaterialNameLength || !isAlnum(name.front())) return false;
  for (char c : name)
    if (!isAlnum(c) && c != '_' && c != '.' && c != '+' && c != '-') return false;
  return true;
}

void checkMaterialName(std::string_view name, const std::string& where) {
  if (isMaterialName(name)) return;
  // The message is one line: control characters of a hostile name are not echoed.
  std::string shown;
  for (char c : name.substr(0, kMaxMaterialNameLength)) shown += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  if (name.size() > kMaxMaterialNameLength) shown += "...";
  throw InputError(where + ": '" + shown + "' is not a usable material name (it names files: letters, digits, '_', '.', "
                   "'+', '-', starting with a letter or digit, at most " + std::to_string(kMaxMaterialNameLength) +
                   " characters)");
}

}  // namespace glossy
