// What names one BRDF — --material F --fit MODEL:METRIC, or --measured
// F.binary (or F.nbrdf), found as every command finds measured data (findMeasured: --merl-dir,
// $GLOSSY_MERL_DIR) — shared by the subcommands that evaluate or sample a single BRDF.
#pragma once

#include "materials/models/brdf.h"

#include <filesystem>
#include <memory>
#include <string>

namespace glossy::app {

struct BrdfOptions {
  std::string material, fit, measured, smoothFresnel, merlDir;

  Brdf load() const;  // InputError naming the file for anything missing or malformed
};

// Loads measured data as the MERL table every lookup reads: a MERL table (NAME.binary, or NAME.binary.xz),
// or a Neural BRDF (NAME.nbrdf) tabulated (materials/nbrdf/neural_brdf.h); with one line on stderr when it
// has unmeasured bins (they evaluate to 0): merl.md asks for the count to be reported wherever the data is
// used.
std::shared_ptr<const MerlTable> loadMeasured(const std::filesystem::path& path);
// How a sheet or an image names that data: "LABEL FILE" with a network's own label ("RGL-EPFL (NBRDF
// reconstruction)"), "MERL (NBRDF reconstruction) FILE" for a table of shared/merl (whose folder says so beside
// them), else "MERL FILE".
std::string measuredLabel(const std::filesystem::path& path);
// The database part of that name: a network's label, "MERL (NBRDF reconstruction)" or "MERL".
std::string measuredDatabase(const std::filesystem::path& path);

// The file a --measured option names, by the one rule every command and the Python module use
// (resolveMeasured, docs/measured.md): an absolute path as given, else under --merl-dir, $GLOSSY_MERL_DIR,
// then the working folder (each also as .xz); InputError naming it when none exists.
std::filesystem::path findMeasured(const std::string& given, const std::filesystem::path& merlDir);

}  // namespace glossy::app
