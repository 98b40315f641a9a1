// Material names: a name becomes a file name (NAME.toml, NAME.exr, NAME.png), so a name read from a file
// or taken from a table's file name must not be able to name a path. One rule for every place that turns a
// name into a file name: letters, digits, '_', '.', '+' and '-', starting with a letter or digit (so never
// "", "." or ".." and never hidden), at most 100 characters. Every MERL material's name fits it.
#pragma once

#include <string>
#include <string_view>

namespace glossy {

constexpr size_t kMaxMaterialNameLength = 100;

bool isMaterialName(std::string_view name);

// Throws InputError "WHERE: 'NAME' is not a usable material name (...)" when `name` breaks the rule.
void checkMaterialName(std::string_view name, const std::string& where);

}  // namespace glossy
