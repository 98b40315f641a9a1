// One material sheet as `glossy report`, `glossy merge sheets` and the study read it back, from the header of
// the layered EXR that `glossy sheet` writes (sheet_exr.cpp, writeSheetExr): the panels in grid order with their
// boxes, labels, notes and fit parameters, each analytic panel's error figures against the measured panel, and
// the verdict, and the settings it was made with. Figures a sheet does not carry (an older sheet, an empty
// panel) are absent, never zero, so the report can show "–" for them and sort them last. Every size and offset
// read from the header is checked in 64-bit arithmetic against the image before it is used.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glossy {

// A figure with its optional 95 % interval.
struct Figure {
  std::optional<double> value, lo, hi;
};

// An image's figures against the measured panel: a panel's (glossy:error.LAYER.*), and the sheet's
// noise-floor row's (glossy:noiseFloor.*: the measured panel against an independent render of itself, what
// each figure shows of noise alone).
struct ImageFigures {
  Figure relativeRmse, luminanceRatio, flip;
  Figure deltaEItp, ssim;  // absent in sheets made before glossy computed them
  std::optional<double> relativeRmseNoisy;
};

struct PanelRecord : ImageFigures {
  std::string layer;   // EXR layer, e.g. "cook_torrance_E2": checked to be a plain name, it names files
  std::string label;   // "CT E2"
  std::string fit;     // "cook-torrance:E2", or "measured"
  std::string note;    // why a panel is empty, or where its data came from
  std::string params;  // the fit's parameters as one line ("" when the sheet does not say)
  std::string colour;  // "#rrggbb" when the sheet gives one
  bool empty = true;
  int x = 0, y = 0, width = 0, height = 0;  // the panel's box in the grid
  std::optional<double> e1, e2;
  std::string noiseFree;  // "yes", or why the noise-free estimate was clamped

  bool isMeasured() const { return fit == "measured"; }
};

// One setting a sheet was made with, as the report compares and shows it.
struct SheetSetting {
  std::string key, label, value;  // "size", "panel size", "256x256"
};

struct SheetRecord {
  std::string name;  // the material's name, glossy:materialName (older sheets: their material file's stem)
  std::filesystem::path exr, png;
  int imageWidth = 0, imageHeight = 0;  // the EXR's, which the sheet's PNG shares
  int panelsBottom = 0;                 // the row below every panel's box
  int pngHeight = 0;                    // the sheet's PNG: its panels, then labels and error maps below
  std::string materialFile;  // glossy:material
  std::string measured;      // glossy:measured: where the measured data came from
  std::string verdict;       // glossy:verdict
  std::string env, scene, spp;
  double pngExposure = 0.0;
  std::optional<double> flipNoiseFloor;  // glossy:flipNoiseFloor: the ꟻLIP render noise alone gives
  std::optional<ImageFigures> noiseFloor;  // absent without a measured panel or in a sheet of format < 3
  // glossy:warnings, one per line: what makes the figures less than they seem (e.g. "noise is up to 93 % of
  // the noisy figure's square: the intervals may be too narrow; …"). While one stands the verdict names no
  // model closest. Empty: none (or a sheet from before warnings were stored).
  std::vector<std::string> warnings;
  std::vector<PanelRecord> panels;  // in grid order
  // What its pixels depend on besides the material (glossy:settings): scene, lighting, panel size, spp,
  // seed, ... — the figures of two sheets compare only when these agree.
  std::vector<SheetSetting> settings;

  const PanelRecord* panel(const std::string& layer) const;
  const PanelRecord* measuredPanel() const;
  // The layers the verdict names: one when a model is closest, several for a tie, none otherwise.
  std::vector<std::string> closestLayers() const;
  bool isTie() const;
};

// Reads the sheet NAME.exr (a regular file inside `folder`) and checks NAME.png beside it. Throws InputError
// naming the file when it is not a readable glossy sheet (not an EXR, no glossy:panels, a panel's box
// outside the image, a size beyond what the report handles, a bad material name, its PNG missing, not a
// PNG or not the EXR's size).
SheetRecord readSheetRecord(const std::filesystem::path& folder, const std::filesystem::path& exr);
inline SheetRecord readSheetRecord(const std::filesystem::path& exr) { return readSheetRecord(exr.parent_path().empty() ? "." : exr.parent_path(), exr); }

// The sheets of a folder (every *.exr), sorted by material name; throws InputError when the folder is
// missing or holds no sheet, when an entry NAME.exr is not a regular file inside it, or when two sheets
// are of one material.
std::vector<SheetRecord> readSheetFolder(const std::filesystem::path& folder);

// Throws InputError naming two sheets made with different settings, and the first setting that differs:
// one index's summary and medians are over sheets made alike.
void checkSameSettings(const std::vector<SheetRecord>& sheets);

}  // namespace glossy
