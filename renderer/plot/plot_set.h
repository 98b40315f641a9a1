// What glossy plot draws: a material's BRDFs in the sheet's order and colours (renderer/sheet/comparison_grid.h:
// the panels --panels names, by default Measured and the six fits of the supplement's grid),
// each present or absent with the reason, and the one channel plotted (R, G, B or luminance). Every figure
// evaluates through value(), so its curves, its CSV and `glossy eval` see the same numbers.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/models/brdf.h"
#include "materials/params/material_file.h"
#include "renderer/plot/chart.h"
#include "renderer/sheet/comparison_grid.h"

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace glossy::plot {

enum class Channel { R, G, B, Luminance };
// "R", "G", "B", "luminance"
std::string channelName(Channel c);

struct PlotBrdf {
  SheetPanel panel;
  bool isMeasured = false;
  bool present = false;
  std::string note;                          // why it is absent; empty when present
  std::optional<Brdf> fit;                   // an analytic fit, when present
  std::shared_ptr<const MerlTable> table;    // the measured data, when present
  CurveStyle style() const;                  // the panel's colour; E1 fits dashed, measured heavier
};

struct PlotSet {
  std::string material;        // the material's name
  std::string measuredLabel;   // the data source ("MERL (NBRDF reconstruction) FILE"), or why there is none
  Channel channel = Channel::Luminance;
  int decades = 0;  // the log scales' span below the peak (glossy plot --decades); 0: down to every curve's floor
  std::vector<PlotBrdf> brdfs;  // in the order of the panels asked for (by default the sheet grid's)

  const PlotBrdf* measured() const;  // null when absent
  std::vector<const PlotBrdf*> present() const;
  // The plotted channel of ρ(L, V) (1/sr), as `glossy eval` computes it from this L and V (normalising them); NaN where the measured table has
  // no data (an unmeasured bin), 0 below the horizon.
  double value(const PlotBrdf& b, const Vec3& L, const Vec3& V) const;
  // "Material alum-bronze; channel luminance; measured data: MERL (NBRDF reconstruction) alum-bronze.binary.xz.":
  // the caption's last line, naming material, channel and data source (by file name, never a local path).
  std::string sourceLine() const;
  // How a log scale from 10^lo to 10^hi was chosen, for the captions: "10^-5 to 10^4, down to the lowest
  // curve's floor" or "… the 9 decades below the peak (--decades)".
  std::string decadesText(int lo, int hi, const std::string& floorWord) const;
  // The fits drawn, "Microfacet E2, Smooth E2, …" and those absent.
  std::string fitsLine() const;
  std::vector<LegendEntry> legend() const;
};

// `d` as `glossy eval` reads it (makeUnitDirection: divided by its length unless it is unit to a few ulps).
// value() applies it to the very pair the CSV prints, as eval does: the same bits reach the lookup, which
// matters on MERL's bin edges, where the slices sit (φ_d = 90°, θ_d = 30°, …) and one rounding picks the
// neighbouring bin.
Vec3 asEvalReads(const Vec3& d);

// The BRDFs of `panels` (glossy plot --panels; by default the sheet's grid) in their order. `measured` null:
// no measured data, `measuredNote` says why.
PlotSet makePlotSet(const MaterialFile& material, std::shared_ptr<const MerlTable> measured, const std::string& measuredNote,
                    Channel channel, std::span<const SheetPanel> panels = sheetPanels());

}  // namespace glossy::plot
