#include "renderer/app/plot_job.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_file.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/destination.h"
#include "renderer/plot/figures.h"
#include "renderer/plot/plot_output.h"
#include "renderer/plot/svg_to_png.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

#include <algorithm>
#include <array>

namespace glossy::app {

namespace {

constexpr std::array<const char*, 4> kChannels = {"R", "G", "B", "luminance"};
constexpr std::array<const char*, 2> kPolarScales = {"log", "linear"};

template <size_t N>
void checkChoice(const std::string& value, const std::array<const char*, N>& choices, const std::string& option) {
  if (std::find(choices.begin(), choices.end(), value) == choices.end())
    throw InputError(option + ": '" + value + "' is none of " + joined(choices, ", "));
}

// Every choice checked before the work starts, in the words of the option or keyword that gave it.
void checkRequest(const PlotRequest& o) {
  checkChoice(o.channel, kChannels, o.channelName);
  checkChoice(o.polarScale, kPolarScales, o.polarScaleName);
  plot::checkPlotKinds(o.figures, o.figuresName);
  if (o.decades < 0 || o.decades > 20)
    throw InputError(o.decadesName + ": must be 1 to 20 (0: down to every curve's floor), not " + std::to_string(o.decades));
}

}  // namespace

PlotRun makePlots(const PlotRequest& o) {
  using namespace plot;
  checkRequest(o);
  const std::vector<SheetPanel> panels = o.panels ? parsePanels(*o.panels, o.panelsName)
                                                  : std::vector<SheetPanel>(sheetPanels().begin(), sheetPanels().end());
  checkOutputFolder(o.out, o.outName);
  const OutputLock lock(o.out, o.outName);
  OwnedFolder out(o.out, kPlotCommand, o.outName);  // a folder of glossy plot's, or new: never `/` or a user's
  const MaterialFile m = loadMaterialFile(o.material);
  // The measured data as the sheets find it: --measured, else the file's own under --merl-dir,
  // $GLOSSY_MERL_DIR or the working folder, else the network embedded beside the material file.
  const std::optional<std::filesystem::path> path =
      o.measured.empty() ? resolveMeasured(m, o.merlDir) : std::optional(findMeasured(o.measured, o.merlDir));
  std::shared_ptr<const MerlTable> table;
  std::string label;
  if (path) {
    table = loadMeasured(*path);
    // Captions and plots.json go into documents and sites: they name the file, never where it lies here.
    label = measuredDatabase(*path) + " " + path->filename().string();
  } else {
    label = m.measured.empty() ? "none (the material names no measured data)"
                               : "none (no " + m.measured + " in --merl-dir or $GLOSSY_MERL_DIR)";
  }
  const Channel channel = o.channel == "R" ? Channel::R : o.channel == "G" ? Channel::G : o.channel == "B" ? Channel::B : Channel::Luminance;
  PlotSet set = makePlotSet(m, table, label, channel, panels);
  set.decades = o.decades;
  const auto rsvg = findRsvgConvert();
  if (!rsvg) note("rsvg-convert is not on PATH: writing the SVGs only; PNGs need librsvg2-bin");
  if (!table) note(m.name + ": no measured data, so no log-ratio images: " + label);
  flushNotes();

  auto wanted = [&](const std::string& kind) {
    return o.figures.empty() || std::find(o.figures.begin(), o.figures.end(), kind) != o.figures.end();
  };
  std::vector<PlotFigure> figures;
  if (wanted("theta_h")) figures.push_back(thetaHFigure(set));
  if (wanted("image_slice"))
    for (PlotFigure& f : imageSliceFigures(set)) figures.push_back(std::move(f));
  if (wanted("albedo")) figures.push_back(albedoFigure(set));
  if (wanted("polar")) figures.push_back(polarFigure(set, o.polarScale == "linear" ? RadialScale::Linear : RadialScale::Log));
  writePlots(out, set, figures, rsvg);
  tell("glossy: wrote " + std::to_string(figures.size()) + (figures.size() == 1 ? " figure of " : " figures of ") + m.name + " to " +
       o.out.string() + " (plots.json)");
  return {m.name, figures.size()};
}

}  // namespace glossy::app
