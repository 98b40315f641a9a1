// Each subcommand registers its options on the parent CLI11 app and returns how to run it.
#pragma once

#include "materials/core/text.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace glossy::cli {

struct Command {
  CLI::App* app;
  std::function<int()> run;  // exit status; throws InputError for bad input
};

Command addErrorCommand(CLI::App& parent);
Command addEvalCommand(CLI::App& parent);
Command addFitCommand(CLI::App& parent);
Command addImportCommand(CLI::App& parent);
Command addListCommand(CLI::App& parent);
Command addRenderCommand(CLI::App& parent);
Command addSampleCommand(CLI::App& parent);
Command addSheetCommand(CLI::App& parent);
Command addSheetsCommand(CLI::App& parent);

// A number > 0 and finite (CLI::PositiveNumber lets "inf" through, and an infinite budget never ends).
inline const CLI::Validator kFinitePositive(
    [](std::string& text) {
      const std::optional<double> v = parseNumber(text);
      return v && std::isfinite(*v) && *v > 0.0 ? std::string() : "must be a finite number > 0, not '" + text + "'";
    },
    "FINITE > 0");

// The committed material library: ./materials when run from a checkout, else the source tree's.
std::filesystem::path defaultMaterialsDir();
// The material files `paths` name, sorted and each once: a folder stands for its *.toml files, anything else
// for itself. No paths: the library.
std::vector<std::filesystem::path> materialFiles(const std::vector<std::string>& paths);

}  // namespace glossy::cli
