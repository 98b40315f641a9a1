// Material parameter files (shared/spec/interfaces.md): one TOML file per material, holding the name, the
// optional measured table and the fits, each fit named MODEL:METRIC.
#pragma once

#include "materials/models/brdf.h"
#include "materials/models/param_set.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glossy {

// A fit's name. A published fit (the paper's, imported) is MODEL:METRIC; glossy's own fit of the same model
// and metric is MODEL:METRIC:glossy, so that the two stand side by side in one file and neither is taken
// for the other.
struct FitId {
  std::string model;   // a registry name: "cook-torrance"
  std::string metric;  // "E1" | "E2" | kNgan05 | kBagher12
  std::string by = {};  // "" for a published fit, kGlossy for a fit `glossy fit` made

  static constexpr std::string_view kGlossy = "glossy";
  // Ngan, Durand & Matusik 2005's own fitting objective, under which their published fits were made: not
  // Löw et al.'s E1 or E2 on glossy's grid, so not labelled as either. Only published fits carry it; glossy
  // neither fits nor evaluates it (`glossy fit --metric` takes E1 and E2; `glossy error` reports E1 and E2
  // of any fit). docs/materials.md.
  static constexpr std::string_view kNgan05 = "Ngan05";
  // Bagher, Soler & Holzschuch 2012's, likewise (their SGD fits of the 100 MERL materials).
  static constexpr std::string_view kBagher12 = "Bagher12";
  // Löw et al.'s metrics, which glossy also fits and reports, as against another paper's own objective.
  bool isLowMetric() const { return metric == "E1" || metric == "E2"; }
  bool isGlossys() const { return by == kGlossy; }
  std::string str() const { return model + ":" + metric + (by.empty() ? "" : ":" + by); }
  bool operator==(const FitId&) const = default;
  // Parses "MODEL:METRIC" or "MODEL:METRIC:glossy"; throws InputError mentioning `context` (e.g. "--fit")
  // when malformed or unknown.
  static FitId parse(std::string_view text, std::string_view context);
};

struct Fit {
  FitId id;
  ParamSet params;
  std::string source;  // provenance of this fit when it differs from the material's
  // Set by `glossy fit`: the error E it reached under its metric, and how it was made (grid, starts); the
  // data it was fitted to (its file name, "alum-bronze.binary.xz", and its database, "MERL (NBRDF
  // reconstruction)") and the day (YYYY-MM-DD, UTC).
  std::optional<double> error;
  std::string settings;
  std::string data, database, date;
  bool operator==(const Fit&) const = default;
};

struct MaterialFile {
  std::string name;
  std::string measured;  // MERL table or .nbrdf network, found by resolveMeasured(); empty if none
  std::string source;
  std::vector<Fit> fits;  // at most one per FitId, kept in the comparison grid's order
  std::filesystem::path path;  // where it was loaded from, for messages; empty if built in memory

  // The fit an id names, as every command and Python look fits up: MODEL:METRIC is the published fit, or
  // glossy's when the file has no published one (a file `glossy fit` started); MODEL:METRIC:glossy is
  // glossy's only. nullptr if none.
  const Fit* find(const FitId& id) const;
  // The fit with exactly this id (a published MODEL:METRIC never stands for glossy's).
  const Fit* findExact(const FitId& id) const;
  // Adds the fit, or replaces the one with exactly the same id; keeps the grid order (a published fit
  // before glossy's of the same model and metric).
  void put(Fit fit);
};

// Anything longer is not a material file (the library's are a few kilobytes).
inline constexpr std::uintmax_t kMaxMaterialFileBytes = 1 << 20;
// Throws InputError "FILE:LINE: fit K (MODEL:METRIC): key 'k' ..." for any missing, unknown, non-finite or
// out-of-range value, and for TOML syntax errors.
MaterialFile loadMaterialFile(const std::filesystem::path& path);
MaterialFile parseMaterialToml(std::string_view text, const std::string& source);
// Checks a fit against its model's declaration (required keys, kinds, bounds, finiteness).
void validateFit(const Fit& fit, const std::string& context);

std::string toToml(const MaterialFile& material);

// The BRDF of one fit; the fit must have been validated.
Brdf makeBrdf(const Fit& fit);

// The file of a material's measured data (its `measured`: a MERL table, NAME.binary or NAME.binary.xz, or a
// Neural BRDF, NAME.nbrdf), looked for in this order: as given if absolute, under merlDir, under
// $GLOSSY_MERL_DIR, in the working folder (each also as NAME.xz); then, for a material file in
// materialDir, the network embedded beside it, materialDir/STEM.nbrdf (STEM: the name's last
// component without .xz, .binary or .nbrdf; docs/measured.md). nullopt when `measured` is empty or
// none exists.
std::optional<std::filesystem::path> resolveMeasured(const std::string& measured, const std::filesystem::path& merlDir = {},
                                                     const std::filesystem::path& materialDir = {});

// The folder of a material file, where what belongs to it sits (its embedded network): the file's own
// folder, "." for a bare file name — so that the rule is the same whatever the working folder, the file's
// folder never being mistaken for "no folder".
std::filesystem::path materialFolder(const std::filesystem::path& materialFile);

// A loaded material's measured data by the rule above, beside the file it was loaded from. Every command
// resolves a material's own data through this, never through its path's parent_path().
std::optional<std::filesystem::path> resolveMeasured(const MaterialFile& material, const std::filesystem::path& merlDir);

// The folders of MERL tables given to a command: `merlDir` (from `option`, "--merl-dir"; skipped when
// empty) and $GLOSSY_MERL_DIR when set and non-empty must each be a folder that exists. A missing one, a
// file or a FIFO would otherwise be passed over in silence and the tables looked for elsewhere; InputError
// "OPTION PATH: ..." (or "$GLOSSY_MERL_DIR PATH: ...").
void checkMerlDirs(const std::filesystem::path& merlDir, std::string_view option = "--merl-dir");

// A new material measured by the MERL table of its name ("alum-bronze" by "alum-bronze.binary").
inline MaterialFile measuredMaterial(const std::string& name, std::string_view source) {
  return {.name = name, .measured = name + ".binary", .source = std::string(source), .fits = {}, .path = {}};
}

}  // namespace glossy
