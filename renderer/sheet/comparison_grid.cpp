#include "renderer/sheet/comparison_grid.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/models/registry.h"

#include <algorithm>

namespace glossy {

namespace {

// The supplement's six first, in its order, then the fits `glossy fit` may add beside them, then the field's
// published fits (Ngan et al. 2005, Bagher et al. 2012) in Paul Tol's muted scheme, also told apart by the
// colour-blind.
constexpr GridFit kGridFits[] = {
    {"microfacet:E2", "#e69f00", true},         {"smooth:E2", "#56b4e9", true},       {"ashikhmin-shirley:E1", "#009e73", true},
    {"ashikhmin-shirley:E2", "#cc79a7", true},  {"cook-torrance:E1", "#0072b2", true}, {"cook-torrance:E2", "#d55e00", true},
    {"microfacet:E1", "#f0e442", false},        {"smooth:E1", "#999999", false},      {"ggx:E2", "#882255", false},
    {"ward:Ngan05", "#332288", false},          {"ward-duer:Ngan05", "#88ccee", false}, {"blinn-phong:Ngan05", "#44aa99", false},
    {"lafortune:Ngan05", "#117733", false},     {"ngan-ashikhmin-shirley:Ngan05", "#999933", false},
    {"ngan-cook-torrance:Ngan05", "#ddcc77", false}, {"sgd:Bagher12", "#cc6677", false}};

constexpr NamedGrid kNamedGrids[] = {
    {"supplement", "", "Löw et al. 2012's grid, the default: Measured and the four models' six published fits"},
    {"lavoue2021",
     "measured,microfacet:E2,smooth:E2,ward:Ngan05,blinn-phong:Ngan05,lafortune:Ngan05,sgd:Bagher12",
     "the approximations Lavoué et al. 2021 asked people to judge (../shared/perceptual): Löw et al.'s ABC (which of "
     "its two E2 fits is not stated: both), Ngan et al.'s Ward, Blinn-Phong and Lafortune, Bagher et al.'s SGD"},
    {"ngan05", "measured,ward:Ngan05,ward-duer:Ngan05,blinn-phong:Ngan05,lafortune:Ngan05,ngan-ashikhmin-shirley:Ngan05,"
               "ngan-cook-torrance:Ngan05",
     "Ngan et al. 2005's six published fits"}};

// A fit the table does not list.
constexpr std::string_view kOtherColour = "#999999";

}  // namespace

std::span<const GridFit> gridFits() { return kGridFits; }

std::vector<GridRow> gridTable() {
  std::vector<GridRow> rows = {{SheetPanel::measured(), true}};
  for (const GridFit& g : kGridFits) rows.push_back({SheetPanel::ofFit(FitId::parse(g.fit, "the sheet grid")), g.inGrid});
  return rows;
}

std::span<const NamedGrid> namedGrids() { return kNamedGrids; }

std::string gridNames() { return joined(kNamedGrids, ", ", [](const NamedGrid& g) { return std::string(g.name); }); }

SheetPanel SheetPanel::measured() { return {"measured", "Measured", "", "#000000"}; }

SheetPanel SheetPanel::ofFit(const FitId& fit) {
  const ModelInfo* model = findModel(fit.model);
  std::string layer = fit.model + "_" + fit.metric + (fit.by.empty() ? "" : "_" + fit.by);
  std::replace(layer.begin(), layer.end(), '-', '_');
  // The paper's label for a published fit; glossy's own fit says so wherever it is shown.
  return {layer, std::string(model ? model->shortLabel : fit.model) + " " + fit.metric + (fit.isGlossys() ? " (glossy fit)" : ""),
          fit.str(), std::string(fitColour(FitId{fit.model, fit.metric}.str()))};
}

std::string_view fitColour(std::string_view fit) {
  const auto row = std::find_if(std::begin(kGridFits), std::end(kGridFits), [&](const GridFit& g) { return g.fit == fit; });
  return row == std::end(kGridFits) ? kOtherColour : row->colour;
}

std::span<const SheetPanel> sheetPanels() {
  static const std::vector<SheetPanel> panels = [] {
    std::vector<SheetPanel> grid;
    for (const GridRow& r : gridTable())
      if (r.inGrid) grid.push_back(r.panel);
    return grid;
  }();
  return panels;
}

std::vector<SheetPanel> parsePanels(std::string_view list, const std::string& option) {
  for (const NamedGrid& g : kNamedGrids)
    if (list == g.name) return g.panels.empty() ? std::vector<SheetPanel>(sheetPanels().begin(), sheetPanels().end()) : parsePanels(g.panels, option);
  const std::string grids = gridNames();
  if (list != "measured" && list.find_first_of(",:") == std::string_view::npos)
    throw InputError(option + ": '" + shortened(list) + "' is not a grid (" + grids + ") nor a comma list of measured and MODEL:METRIC");
  std::vector<SheetPanel> panels;
  for (size_t start = 0; start <= list.size();) {
    const size_t end = std::min(list.find(',', start), list.size());
    const std::string_view item = list.substr(start, end - start);
    start = end + 1;
    if (item.empty())
      throw InputError(option + ": '" + shortened(list) + "' has an empty panel (a grid's name, " + grids +
                       ", or a comma list of measured and MODEL:METRIC)");
    SheetPanel panel = item == "measured" ? SheetPanel::measured() : SheetPanel::ofFit(FitId::parse(item, option));
    if (std::any_of(panels.begin(), panels.end(), [&](const SheetPanel& p) { return p.layer == panel.layer; }))
      throw InputError(option + ": '" + shortened(item) + "' is named twice");
    panels.push_back(std::move(panel));
  }
  return panels;
}

std::string panelList(std::span<const SheetPanel> panels) {
  return joined(panels, ",", [](const SheetPanel& p) { return p.fit.empty() ? std::string("measured") : p.fit; });
}

}  // namespace glossy
