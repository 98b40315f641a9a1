// Writing glossy plot's output folder: per figure NAME.svg, NAME.csv and NAME.png (when rsvg-convert is
// there), and the index plots.json that the report reads:
//   {"material", "measured" (the data-source label), "channel",
//    "figures": [{"kind", "title", "caption", "svg", "png", "csv"}]}   (file names relative to the folder;
//    "png" null when no PNG was made)
// Every file is written atomically; plots.json last, so a folder with an index is whole. The folder is
// glossy plot's own (renderer/output/owned_folder.h): a run writes into a missing or empty folder or an
// earlier plot folder, and replaces only what glossy plot wrote there.
#pragma once

#include "renderer/output/owned_folder.h"
#include "renderer/plot/figure.h"
#include "renderer/plot/plot_set.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glossy::plot {

// The kinds of figure, as plots.json names them (and --figures, --plot-kinds choose them).
inline constexpr std::array<const char*, 4> kPlotKinds = {"theta_h", "image_slice", "albedo", "polar"};

// Throws InputError, in the words of `option` ("--figures", "plot_kinds"), for a kind not in kPlotKinds.
void checkPlotKinds(const std::vector<std::string>& kinds, const std::string& option);

// The command that fills a plot folder, as its manifest names it.
inline constexpr const char* kPlotCommand = "glossy plot";

// `rsvgConvert` nullopt: no PNGs. `dir` was checked (OwnedFolder's constructor) before the figures were made.
void writePlots(OwnedFolder& dir, const PlotSet& set, const std::vector<PlotFigure>& figures,
                const std::optional<std::filesystem::path>& rsvgConvert);

}  // namespace glossy::plot
