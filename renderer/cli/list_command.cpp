// glossy list: the material library at a glance, a section per database folder, with each fit's head-on
// albedo (the job: renderer/app/list_job.h), or the comparison grid's table as JSON.
#include "materials/core/text.h"
#include "renderer/app/list_job.h"
#include "renderer/cli/command.h"
#include "renderer/sheet/comparison_grid.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

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

int runList(const ListOptions& o) {
  if (o.grid) return printGrid();
  const app::Listing listing = app::listLibrary(o.paths, o.merlDir, o.panelsOption->count() ? std::optional(o.panels) : std::nullopt);
  std::printf("Head-on directional albedo a(N) = ∫ρ(L,N) cos θ_L dω_L of each fit (mean of R, G, B), a section\n"
              "per database folder; 'measured' says whether the material's MERL table was found (--merl-dir,\n"
              "$GLOSSY_MERL_DIR), or only the Neural BRDF network beside it ('network'); 'other fits' are the fits\n"
              "no column shows (models outside the grid, glossy's refits beside the published ones).\n");
  for (const app::ListedFolder& section : listing.folders) {
    const size_t n = section.materials.size();
    std::printf("\n%s%s%s, %zu material%s\n", section.database.c_str(), section.database.empty() ? "" : " — ",
                section.folder.empty() ? "." : section.folder.string().c_str(), n, n == 1 ? "" : "s");
    std::printf("%-26s %-9s", "material", "measured");
    for (const SheetPanel& c : listing.columns) std::printf(" %*s", width(c), c.label.c_str());
    std::printf("  other fits\n");
    for (const app::ListedMaterial& m : section.materials) {
      if (!m.error.empty()) {
        std::cerr << "glossy: " << m.error << "\n";
        continue;
      }
      std::printf("%-26s %-9s", m.name.c_str(), m.measured.c_str());
      for (size_t k = 0; k < listing.columns.size(); ++k)
        if (m.albedo[k]) std::printf(" %*.4f", width(listing.columns[k]), *m.albedo[k]);
        else std::printf(" %*s", width(listing.columns[k]), "-");
      std::string others;
      for (const auto& [id, albedo] : m.otherFits) others += formatted("%s%s %.4f", others.empty() ? "  " : ", ", id.c_str(), albedo);
      std::printf("%s\n", others.c_str());
    }
  }
  std::printf("\n%zu materials, %d of the %s fits, %d other fits", listing.materials, listing.fits,
              listing.namedColumns ? "named" : "grid's", listing.otherFits);
  if (listing.unreadable) std::printf(", %zu unreadable (see stderr)", listing.unreadable);
  std::printf("\n");
  return listing.unreadable ? 2 : 0;
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
