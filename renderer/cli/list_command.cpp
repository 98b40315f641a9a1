// glossy list: the material library at a glance, a section per database folder, with each fit's head-on
// albedo.
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/models/albedo.h"
#include "materials/nbrdf/neural_brdf.h"
#include "materials/params/material_file.h"
#include "renderer/cli/command.h"
#include "renderer/sheet/comparison_grid.h"
#include "renderer/util/data_dir.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <set>

namespace glossy::cli {

namespace {

struct ListOptions {
  std::vector<std::string> paths;
  std::string merlDir;
  std::string panels;
  CLI::Option* panelsOption = nullptr;
  bool grid = false;
};

// The comparison grid's table as JSON, a row per panel (glossy.comparison_grid() gives the same rows): what
// scripts read instead of restating the grid or its colours.
int printGrid() {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const auto& [p, inGrid] : gridTable())
    rows.push_back({{"fit", p.fit.empty() ? std::string("measured") : p.fit}, {"layer", p.layer}, {"label", p.label},
                    {"colour", p.colour}, {"default", inGrid}});
  std::cout << rows.dump(1) << "\n";
  return 0;
}

// A column per fit of the sheets' comparison grid.
int width(const SheetPanel& column) { return std::max(9, int(column.label.size())); }

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

int runList(const ListOptions& o) {
  if (o.grid) return printGrid();
  // The grid's fits, or the fits --panels names (those outside the grid: Ngan et al.'s, glossy's own).
  const std::vector<SheetPanel> columns = o.panelsOption->count() == 0 ? std::vector<SheetPanel>(sheetPanels().begin(), sheetPanels().end())
                                                                       : parsePanels(o.panels, "--panels");
  const auto files = materialFiles(o.paths);
  if (files.empty()) throw InputError((o.paths.empty() ? materialLibraryDir().string() : o.paths.front()) + ": no .toml material files");

  std::printf("Head-on directional albedo a(N) = ∫ρ(L,N) cos θ_L dω_L of each fit (mean of R, G, B), a section\n"
              "per database folder; 'measured' says whether the material's MERL table was found (--merl-dir,\n"
              "$GLOSSY_MERL_DIR), or only the Neural BRDF network beside it ('network'); 'other fits' are the fits\n"
              "no column shows (models outside the grid, glossy's refits beside the published ones).\n");
  // A section per folder, headed by its database; the files of each come sorted from materialFiles.
  std::map<std::filesystem::path, std::vector<std::filesystem::path>> byFolder;
  for (const auto& file : files) byFolder[file.parent_path()].push_back(file);
  int bad = 0, fits = 0, otherFits = 0;
  for (const auto& [folder, members] : byFolder) {
    const std::string label = databaseLabel(folder);
    std::printf("\n%s%s%s, %zu material%s\n", label.c_str(), label.empty() ? "" : " — ",
                folder.empty() ? "." : folder.string().c_str(), members.size(), members.size() == 1 ? "" : "s");
    std::printf("%-26s %-9s", "material", "measured");
    for (const SheetPanel& c : columns)
      if (!c.fit.empty()) std::printf(" %*s", width(c), c.label.c_str());
    std::printf("  other fits\n");
    for (const auto& file : members) {
      MaterialFile m;
      try {
        m = loadMaterialFile(file);
      } catch (const InputError& e) {
        std::cerr << "glossy: " << e.what() << "\n";
        ++bad;
        continue;
      }
      std::printf("%-26s %-9s", m.name.c_str(), measuredState(m, o.merlDir).c_str());
      const auto albedo = [](const Fit& f) {
        const Rgb a = albedoAtNormalIncidence(makeBrdf(f));
        return (a.r + a.g + a.b) / 3.0;
      };
      std::set<const Fit*> shown;
      for (const SheetPanel& c : columns) {
        if (c.fit.empty()) continue;
        const Fit* f = m.find(FitId::parse(c.fit, c.label));
        if (!f) {
          std::printf(" %*s", width(c), "-");
          continue;
        }
        std::printf(" %*.4f", width(c), albedo(*f));
        shown.insert(f);
        ++fits;
      }
      // The fits no column shows (a model outside the grid, glossy's refits beside the paper's), by id.
      std::string others;
      for (const Fit& f : m.fits)
        if (!shown.count(&f)) {
          others += formatted("%s%s %.4f", others.empty() ? "  " : ", ", f.id.str().c_str(), albedo(f));
          ++otherFits;
        }
      std::printf("%s\n", others.c_str());
    }
  }
  std::printf("\n%zu materials, %d of the %s fits, %d other fits", files.size() - size_t(bad), fits,
              o.panelsOption->count() == 0 ? "grid's" : "named", otherFits);
  if (bad) std::printf(", %d unreadable (see stderr)", bad);
  std::printf("\n");
  return bad ? 2 : 0;
}

}  // namespace

Command addListCommand(CLI::App& parent) {
  auto o = std::make_shared<ListOptions>();
  CLI::App* app = parent.add_subcommand("list",
      "List material parameter files with the head-on albedo of each fit of the comparison grid, or of the fits "
      "--panels names (a quick consistency check: the fits of one material should roughly agree).");
  app->add_option("paths", o->paths,
                  "Material files or folders, listed by folder (default: the committed library, materials/library/, "
                  "a section per database)");
  app->add_option("--merl-dir", o->merlDir, "Folder holding the MERL .binary tables");
  o->panelsOption = app->add_option("--panels", o->panels,
                                    "Columns instead of the grid's fits: a grid's name (" + gridNames() + ") or a comma list of "
                                    "MODEL:METRIC[:glossy], e.g. ward:Ngan05,blinn-phong:Ngan05 (Ngan et al. 2005's published fits)");
  app->add_flag("--grid", o->grid,
                "Print the comparison grid's table instead, as JSON: a row per panel (fit, EXR layer, label, colour, whether "
                "the default grid shows it), in the grid's order")
      ->excludes(o->panelsOption);
  return {app, [o] { return runList(*o); }};
}

}  // namespace glossy::cli
