// What the report shows of one material sheet, read from the header of the layered EXR that `glossy sheet`
// writes (renderer/sheet/sheet.cpp, writeSheetExr): the panels in grid order with their boxes, labels,
// notes and fit parameters, each analytic panel's error figures against the measured panel, and the
// verdict. Figures a sheet does not carry (an older sheet, an empty panel) are absent, never zero, so the
// report can show "–" for them and sort them last.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glossy::report {

// A figure with its optional 95 % interval.
struct Figure {
  std::optional<double> value, lo, hi;
};

struct PanelRecord {
  std::string layer;   // EXR layer, e.g. "cook_torrance_E2": checked to be a plain name, it names files
  std::string label;   // "CT E2"
  std::string fit;     // "cook-torrance:E2", or "measured"
  std::string note;    // why a panel is empty, or where its data came from
  std::string params;  // the fit's parameters as one line ("" when the sheet does not say)
  std::string colour;  // "#rrggbb" when the sheet gives one
  bool empty = true;
  int x = 0, y = 0, width = 0, height = 0;  // the panel's box in the grid
  Figure relativeRmse, luminanceRatio, flip;
  std::optional<double> relativeRmseNoisy, e1, e2;
  std::string noiseFree;  // "yes", or why the noise-free estimate was clamped

  bool isMeasured() const { return fit == "measured"; }
};

struct SheetRecord {
  std::string name;          // the sheet's file stem, a material name
  std::filesystem::path exr, png;
  std::string materialFile;  // glossy:material
  std::string measured;      // glossy:measured: where the measured data came from
  std::string verdict;       // glossy:verdict
  std::string env, scene, spp;
  double pngExposure = 0.0;
  std::optional<double> flipNoiseFloor;  // glossy:flipNoiseFloor: the ꟻLIP render noise alone gives
  std::vector<PanelRecord> panels;  // in grid order

  const PanelRecord* panel(const std::string& layer) const;
  const PanelRecord* measuredPanel() const;
  // The layers the verdict names: one when a model is closest, several for a tie, none otherwise.
  std::vector<std::string> closestLayers() const;
  bool isTie() const;
};

// Reads the sheet NAME.exr and checks NAME.png beside it. Throws InputError naming the file when it is not
// a readable glossy sheet (not an EXR, no glossy:panels, a panel's box outside the image, a bad name).
SheetRecord readSheetRecord(const std::filesystem::path& exr);

// The sheets of a folder (every *.exr), sorted by name; throws InputError when the folder is missing or
// holds no sheet.
std::vector<SheetRecord> readSheetFolder(const std::filesystem::path& folder);

}  // namespace glossy::report
