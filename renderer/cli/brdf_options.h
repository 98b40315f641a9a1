// The options that name one BRDF on the command line — --material F --fit MODEL:METRIC, or --measured
// F.binary — shared by the subcommands that evaluate or sample a single BRDF.
#pragma once

#include "materials/models/brdf.h"

#include <CLI/CLI.hpp>

#include <string>

namespace glossy::cli {

struct BrdfOptions {
  std::string material, fit, measured, smoothFresnel;

  void addTo(CLI::App* app);
  Brdf load() const;  // InputError naming the file for anything missing or malformed
};

// One line on stderr when a measured table has unmeasured bins (they evaluate to 0): merl.md asks for
// the count to be reported wherever the data is used.
void reportInvalidBins(const MerlTable& table);

}  // namespace glossy::cli
