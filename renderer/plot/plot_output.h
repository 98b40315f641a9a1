// Writing glossy plot's output folder: per figure NAME.svg, NAME.csv and NAME.png (when rsvg-convert is
// there), and the index plots.json that the report reads:
//   {"material", "measured" (the data-source label), "channel",
//    "figures": [{"kind", "title", "caption", "svg", "png", "csv"}]}   (file names relative to the folder;
//    "png" null when no PNG was made)
// Every file is written atomically; plots.json last, so a folder with an index is whole.
#pragma once

#include "renderer/plot/figure.h"
#include "renderer/plot/plot_set.h"

#include <filesystem>
#include <optional>
#include <vector>

namespace glossy::plot {

// `rsvgConvert` nullopt: no PNGs.
void writePlots(const std::filesystem::path& dir, const PlotSet& set, const std::vector<PlotFigure>& figures,
                const std::optional<std::filesystem::path>& rsvgConvert);

}  // namespace glossy::plot
