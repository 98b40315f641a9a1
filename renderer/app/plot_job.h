// glossy plot's job without the command line: a material's fits and measured data as figures — θ_h slices,
// image slices with the log-ratio to the measured data, directional albedo, in-plane polar lobes — each as
// SVG, PNG (with rsvg-convert) and CSV, indexed by plots.json (renderer/plot/, docs/plots.md). `glossy plot`
// and the Python module's glossy.plot run it, so the two write the same files.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glossy::app {

struct PlotRequest {
  std::filesystem::path material;           // the material's parameter file
  std::string measured;                     // measured data instead of the file's own ("": the file's)
  std::filesystem::path merlDir;            // MERL tables (else $GLOSSY_MERL_DIR)
  std::filesystem::path out;                // the output folder: new, empty, or an earlier glossy plot's
  std::string outName = "-o";               // what messages call it: the option that gave it
  std::string channel = "luminance";        // R, G, B or luminance
  std::string polarScale = "log";           // log or linear
  std::optional<std::string> panels;        // the BRDFs, as a sheet's panels; unset: the default grid
  std::string panelsName = "--panels";      // what messages call them
  std::vector<std::string> figures;         // the kinds to draw (plot::kPlotKinds); empty: all
  int decades = 0;                          // below the peak, 1–20; 0: down to every curve's floor
  // What messages call the other options: the command line's, or Python's keywords.
  std::string channelName = "--channel", polarScaleName = "--polar-scale", figuresName = "--figures", decadesName = "--decades";
};

struct PlotRun {
  std::string material;  // its name
  size_t figures = 0;
};

// InputError naming the file or option for bad input (an unknown channel, scale or figure kind among them),
// before anything is written.
PlotRun makePlots(const PlotRequest& request);

}  // namespace glossy::app
