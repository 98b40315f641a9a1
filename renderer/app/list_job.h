// glossy list's job without the command line: the material library at a glance — a section per database
// folder, each material's measured data found or not, and each fit's head-on albedo (a quick consistency
// check: the fits of one material should roughly agree). `glossy list` prints it as a table; the Python
// module's glossy.list_library returns it.
#pragma once

#include "renderer/sheet/comparison_grid.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace glossy::app {

struct ListedMaterial {
  std::filesystem::path file;
  std::string error;     // why the file could not be read ("" when it was): the rest is then empty
  std::string name;
  std::string measured;  // "found" (a table), "network" (only the embedded Neural BRDF), "missing", "-" (names none)
  std::vector<std::optional<double>> albedo;               // per column: the fit's head-on albedo (mean of R, G, B)
  std::vector<std::pair<std::string, double>> otherFits;  // the fits no column shows, by id, with theirs
};

struct ListedFolder {
  std::filesystem::path folder;
  std::string database;  // as its networks label themselves ("MERL (NBRDF reconstruction)"); "" without networks
  std::vector<ListedMaterial> materials;
};

struct Listing {
  std::vector<SheetPanel> columns;  // the grid's fits, or those `panels` names (the measured panel has no column)
  bool namedColumns = false;        // `panels` chose them
  std::vector<ListedFolder> folders;
  size_t materials = 0, unreadable = 0;
  int fits = 0, otherFits = 0;
};

// The files `paths` name (material_files.h; none: the library). Head-on directional albedo a(N) = ∫ρ(L,N)
// cos θ_L dω_L. InputError when no file is found, or for a bad panel list (named `panelsName`); a file
// that cannot be read is listed with its error.
Listing listLibrary(const std::vector<std::string>& paths, const std::string& merlDir, const std::optional<std::string>& panels,
                    const std::string& panelsName = "--panels");

}  // namespace glossy::app
