#include "renderer/app/list_job.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/models/albedo.h"
#include "materials/nbrdf/neural_brdf.h"
#include "materials/params/material_file.h"
#include "renderer/app/material_files.h"
#include "renderer/util/data_dir.h"

#include <map>
#include <set>

namespace glossy::app {

namespace {

// "found" (a table), "network" (only the embedded Neural BRDF), "missing", or "-" when it names none.
std::string measuredState(const MaterialFile& m, const std::string& merlDir) {
  if (m.measured.empty()) return "-";
  const auto path = resolveMeasured(m, merlDir);
  return !path ? "missing" : path->extension() == ".nbrdf" ? "network" : "found";
}

// A folder's database, as its networks label themselves ("MERL (NBRDF reconstruction)"); the labels joined
// if they differ, empty without networks. A network that does not load names nothing here: list reads
// material files, and the commands that read the network report it.
std::string databaseLabel(const std::filesystem::path& folder) {
  std::set<std::string> labels;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder.empty() ? "." : folder, ec)) {
    if (e.path().extension() != ".nbrdf" || !e.is_regular_file(ec)) continue;
    try {
      labels.insert(NeuralBrdf::load(e.path()).label());
    } catch (const InputError&) {
    }
  }
  return joined(labels, "; ");
}

double meanAlbedo(const Fit& f) {
  const Rgb a = albedoAtNormalIncidence(makeBrdf(f));
  return (a.r + a.g + a.b) / 3.0;
}

ListedMaterial listed(const std::filesystem::path& file, const std::vector<SheetPanel>& columns, const std::string& merlDir,
                      Listing& listing) {
  ListedMaterial row;
  row.file = file;
  MaterialFile m;
  try {
    m = loadMaterialFile(file);
  } catch (const InputError& e) {
    row.error = e.what();
    ++listing.unreadable;
    return row;
  }
  row.name = m.name;
  row.measured = measuredState(m, merlDir);
  std::set<const Fit*> shown;
  for (const SheetPanel& c : columns) {
    const Fit* f = m.find(FitId::parse(c.fit, c.label));
    row.albedo.push_back(f ? std::optional(meanAlbedo(*f)) : std::nullopt);
    if (f) shown.insert(f), ++listing.fits;
  }
  // The fits no column shows (a model outside the grid, glossy's refits beside the paper's), by id.
  for (const Fit& f : m.fits)
    if (!shown.count(&f)) row.otherFits.emplace_back(f.id.str(), meanAlbedo(f)), ++listing.otherFits;
  ++listing.materials;
  return row;
}

}  // namespace

Listing listLibrary(const std::vector<std::string>& paths, const std::string& merlDir, const std::optional<std::string>& panels,
                    const std::string& panelsName) {
  Listing listing;
  // The grid's fits, or the fits `panels` names (those outside the grid: Ngan et al.'s, glossy's own).
  for (const SheetPanel& p : panels ? parsePanels(*panels, panelsName) : std::vector<SheetPanel>(sheetPanels().begin(), sheetPanels().end()))
    if (!p.fit.empty()) listing.columns.push_back(p);
  listing.namedColumns = panels.has_value();
  const auto files = materialFiles(paths);
  if (files.empty()) throw InputError((paths.empty() ? materialLibraryDir().string() : paths.front()) + ": no .toml material files");
  // A section per folder, headed by its database; the files of each come sorted from materialFiles.
  std::map<std::filesystem::path, std::vector<std::filesystem::path>> byFolder;
  for (const auto& file : files) byFolder[file.parent_path()].push_back(file);
  for (const auto& [folder, members] : byFolder) {
    ListedFolder section{folder, databaseLabel(folder), {}};
    for (const auto& file : members) section.materials.push_back(listed(file, listing.columns, merlDir, listing));
    listing.folders.push_back(std::move(section));
  }
  return listing;
}

}  // namespace glossy::app
