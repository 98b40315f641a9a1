// The comparison grid: the panels a material sheet can show, each with its EXR layer, label and colour —
// the one table of them, which sheets, plots (renderer/plot/plot_set.h), the report and Python
// (glossy.comparison_grid()) read. A panel is the measured data or a fit, MODEL:METRIC, of any model the
// registry knows (materials/models/registry.h: its short label names the panel); the table below adds the
// supplement's grid, Measured | Microfacet E2 | Smooth E2 | AS E1 | AS E2 | CT E1 | CT E2, and each fit's
// colour (Okabe-Ito, told apart by the colour-blind). A new model is a panel as soon as it is registered;
// a line in the table gives it a colour of its own.
#pragma once

#include "materials/params/material_file.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glossy {

struct SheetPanel {
  std::string layer;  // EXR layer: "measured", "microfacet_E2", ...
  std::string label;  // for people: "Measured", "Microfacet E2", ...
  std::string fit;    // MODEL:METRIC; empty for the measured panel
  std::string colour; // "#rrggbb": the panel's colour in plots and the report

  static SheetPanel measured();
  // Layer "cook_torrance_E2", label "CT E2": the model's short label and the metric; glossy's own fit says so.
  static SheetPanel ofFit(const FitId& fit);
};

// A row of the table: a fit, its colour, and whether the supplement's grid shows it.
struct GridFit {
  std::string_view fit;
  std::string_view colour;
  bool inGrid;
};
std::span<const GridFit> gridFits();
// A fit's colour (MODEL:METRIC, as the table names it): its row's, or one grey for a fit the table lacks.
std::string_view fitColour(std::string_view fit);

// The table as the front ends show it (glossy list --grid, glossy.comparison_grid()): the measured panel, then
// each row's fit as its panel, with whether the supplement's grid shows it.
struct GridRow {
  SheetPanel panel;
  bool inGrid;
};
std::vector<GridRow> gridTable();

// The supplement's grid, the default panels: Measured, then its six fits in its order.
std::span<const SheetPanel> sheetPanels();

// A grid --panels takes by its name, beside the supplement's: the panels a question needs (namedGrids()).
struct NamedGrid {
  std::string_view name;
  std::string_view panels;  // as --panels takes them; empty: the supplement's grid, sheetPanels()
  std::string_view description;
};
std::span<const NamedGrid> namedGrids();
// Their names for help and messages: "supplement, lavoue2021, ngan05".
std::string gridNames();

// The panels --panels names: a grid's name (namedGrids()), or a comma list of "measured" and MODEL:METRIC
// fits, in the order given. InputError naming `option` and the value for an empty list or item, an
// unknown model or metric, or a panel named twice.
std::vector<SheetPanel> parsePanels(std::string_view list, const std::string& option);
// The list back, as parsePanels reads it: "measured,microfacet:E2,...".
std::string panelList(std::span<const SheetPanel> panels);

}  // namespace glossy
