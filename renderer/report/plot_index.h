// The figures `glossy plot` made for one material: PLOTS_DIR/NAME/plots.json lists them
// ({"material", "measured", "channel", "figures": [{"kind", "title", "caption", "svg", "png", "csv"}]}) with
// the files beside it. The report copies the files into the site, so every file name is checked to be a
// plain name of an existing file in that folder: a plots.json cannot make the report read or write
// anywhere else. Every file is a regular file inside PLOTS_DIR
// (renderer/output/input_folder.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::report {

struct PlotFigure {
  std::string kind, title, caption;
  std::string png, svg, csv;  // plain file names in the plots folder; "" when absent
  std::string shown;          // the site's file the page shows: the scaled picture (plot_picture.h), or the SVG
};

struct PlotIndex {
  std::filesystem::path folder;  // PLOTS_DIR/NAME
  std::string material, measured, channel;
  std::vector<PlotFigure> figures;
};

// Reads folder/plots.json, `folder` being PLOTS_DIR/NAME; throws InputError naming the file for malformed
// JSON, a missing field, a file name that is not plain, or a named file that is missing, not a regular file
// or a symlink leading out of `plotsDir`. Every figure has a PNG or an SVG.
PlotIndex readPlotIndex(const std::filesystem::path& plotsDir, const std::filesystem::path& folder);

}  // namespace glossy::report
