// TOML files as input: parsing with errors that name the file, line and column, and the "FILE:LINE: "
// prefix that points a message at a node. Shared by every TOML format glossy reads (material files,
// Neural BRDF networks).
#pragma once

#include "materials/core/input_error.h"

#include <toml++/toml.h>

#include <optional>
#include <string>
#include <string_view>

namespace glossy {

// The document's root table; InputError "FILE:LINE:COLUMN: TOML syntax error: …" when it is not TOML.
inline toml::table parseToml(std::string_view text, const std::string& source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& pos = e.source().begin;
    throw InputError(source + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
}

// A number, integer or floating point; nullopt for anything else.
inline std::optional<double> tomlNumber(const toml::node& node) {
  if (const auto* i = node.as_integer()) return double(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

// "FILE:LINE: " for a node with a known position, else "FILE: ".
inline std::string tomlAt(const std::string& source, const toml::node& node) {
  const auto& pos = node.source().begin;
  return pos.line == 0 ? source + ": " : source + ":" + std::to_string(pos.line) + ": ";
}

}  // namespace glossy
