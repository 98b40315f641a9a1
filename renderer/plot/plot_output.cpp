#include "renderer/plot/plot_output.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/util/atomic_file.h"
#include "renderer/plot/svg_to_png.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace glossy::plot {

namespace {

constexpr double kPngZoom = 1.5;  // 1.5 px per SVG unit: sharp text in documents and on screens

}  // namespace

void checkPlotKinds(const std::vector<std::string>& kinds, const std::string& option) {
  for (const std::string& kind : kinds)
    if (std::find(kPlotKinds.begin(), kPlotKinds.end(), kind) == kPlotKinds.end())
      throw InputError(option + ": '" + shortened(kind) + "' is none of " + joined(kPlotKinds, ", "));
}

void writePlots(OwnedFolder& dir, const PlotSet& set, const std::vector<PlotFigure>& figures,
                const std::optional<std::filesystem::path>& rsvgConvert) {
  std::vector<std::string> files = {"plots.json"};
  for (const PlotFigure& f : figures)
    for (const char* ext : {".svg", ".csv", ".png"})
      if (rsvgConvert || std::string(ext) != ".png") files.push_back(f.name + ext);
  dir.plan(files);
  nlohmann::ordered_json index;
  index["material"] = set.material;
  index["measured"] = set.measuredLabel;
  index["channel"] = channelName(set.channel);
  index["figures"] = nlohmann::ordered_json::array();
  for (const PlotFigure& f : figures) {
    const std::filesystem::path svg = dir.path(f.name + ".svg"), csv = dir.path(f.name + ".csv"), png = dir.path(f.name + ".png");
    writeFileAtomically(svg, f.svg);
    writeFileAtomically(csv, f.csv);
    if (rsvgConvert) svgToPng(*rsvgConvert, svg, png, kPngZoom);
    nlohmann::ordered_json entry;
    entry["kind"] = f.kind;
    entry["title"] = f.title;
    entry["caption"] = joined(f.caption, " ");
    entry["svg"] = svg.filename().string();
    entry["png"] = rsvgConvert ? nlohmann::ordered_json(png.filename().string()) : nlohmann::ordered_json(nullptr);
    entry["csv"] = csv.filename().string();
    index["figures"].push_back(entry);
  }
  writeFileAtomically(dir.path("plots.json"), index.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
  dir.finish();
}

}  // namespace glossy::plot
