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
Command addMergeCommand(CLI::App& parent);
Command addPlotCommand(CLI::App& parent);
Command addRenderCommand(CLI::App& parent);
Command addReportCommand(CLI::App& parent);
Command addSampleCommand(CLI::App& parent);
Command addSheetCommand(CLI::App& parent);
Command addSheetsCommand(CLI::App& parent);

// A finite number in [lo, hi] (or (lo, hi] when loOpen). CLI::PositiveNumber lets "inf" through, and an
// infinite budget never ends; CLI11's own ranges print a double's limits with std::to_string (309 digits).
inline CLI::Validator finiteIn(double lo, double hi, bool loOpen = false) {
  const std::string range = formatted("%s%g, %g]", loOpen ? "(" : "[", lo, hi);
  return CLI::Validator(
      [lo, hi, loOpen, range](std::string& text) {
        const std::optional<double> v = parseNumber(text);
        const bool ok = v && std::isfinite(*v) && (loOpen ? *v > lo : *v >= lo) && *v <= hi;
        return ok ? std::string() : "must be a finite number in " + range + ", not '" + shortened(text) + "'";
      },
      "NUMBER in " + range);
}
// A whole number in [lo, hi], with the same short message.
inline CLI::Validator integerIn(long long lo, long long hi) {
  const std::string range = formatted("[%lld, %lld]", lo, hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) {
        const std::optional<double> v = parseNumber(text);
        const bool ok = v && std::isfinite(*v) && *v == std::floor(*v) && *v >= double(lo) && *v <= double(hi);
        return ok ? std::string() : "must be a whole number in " + range + ", not '" + shortened(text) + "'";
      },
      "INT in " + range);
}

// Threads a command may be asked for: far beyond any machine's cores, well short of what exhausts memory
// creating them (`--threads 1e8`).
inline constexpr int kMaxThreads = 4096;

// The committed material library, a folder per database: ./materials/library when run from a checkout, else
// the source tree's (or the Python package's).
std::filesystem::path defaultMaterialsDir();
// The material files `paths` name, sorted and each once: a folder stands for the *.toml files in it and its
// subfolders, anything else for itself. No paths: the library.
std::vector<std::filesystem::path> materialFiles(const std::vector<std::string>& paths);

}  // namespace glossy::cli
