// glossy plot: a material's BRDFs as figures — θ_h slices, image slices with the log-ratio to measured data,
// directional albedo, in-plane polar lobes — each as SVG, PNG and the CSV of its numbers, indexed by
// plots.json (renderer/plot/, docs/plots.md).
#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"
#include "materials/params/material_file.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/destination.h"
#include "renderer/cli/command.h"
#include "renderer/plot/figures.h"
#include "renderer/plot/plot_output.h"
#include "renderer/plot/svg_to_png.h"

#include <algorithm>
#include <iostream>
#include <memory>

namespace glossy::cli {

namespace {

struct PlotOptions {
  std::string material, measured, channel = "luminance", polarScale = "log", panels;
  int decades = 0;  // 0: the log scales follow the data
  CLI::Option* panelsOption = nullptr;
  std::vector<std::string> figures;  // kinds to draw; empty: all
  std::filesystem::path merlDir, out;
};

int runPlot(const PlotOptions& o) {
  using namespace plot;
  const std::vector<SheetPanel> panels = o.panelsOption->count() == 0 ? std::vector<SheetPanel>(sheetPanels().begin(), sheetPanels().end())
                                                          : parsePanels(o.panels, "--panels");
  checkOutputFolder(o.out, "-o");
  const OutputLock lock(o.out, "-o");
  OwnedFolder out(o.out, kPlotCommand, "-o");  // a folder of glossy plot's, or new: never `/` or a user's
  const MaterialFile m = loadMaterialFile(o.material);
  // The measured data as the sheets find it: --measured, else the file's own under --merl-dir,
  // $GLOSSY_MERL_DIR or the working folder, else the network embedded beside the material file.
  const std::optional<std::filesystem::path> path =
      o.measured.empty() ? resolveMeasured(m, o.merlDir)
                         : std::optional(findMeasured(o.measured, o.merlDir));
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
  std::cerr << "glossy: wrote " << figures.size() << (figures.size() == 1 ? " figure of " : " figures of ") << m.name << " to "
            << o.out.string() << " (plots.json)\n";
  return 0;
}

}  // namespace

Command addPlotCommand(CLI::App& parent) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* app = parent.add_subcommand("plot",
      "Plot a material's fits and its measured data: θh slices, θh×θd image slices with the log-ratio to measured, "
      "directional albedo, in-plane polar lobes; SVG, PNG (with rsvg-convert) and the CSV of every curve, indexed by "
      "DIR/plots.json (docs/plots.md)");
  app->add_option("--material", o->material, "Material parameter file (TOML)")->required();
  app->add_option("--measured", o->measured,
                  "Measured data instead of the file's own: a MERL .binary (or .binary.xz) table or a .nbrdf network");
  app->add_option("--merl-dir", o->merlDir, "Folder with MERL tables (else $GLOSSY_MERL_DIR)");
  app->add_option("-o,--out", o->out,
                  "Output folder: created if missing; an existing one must be empty or an earlier glossy plot's, whose files "
                  "it replaces")
      ->required();
  app->add_option("--channel", o->channel, "Which channel to plot: R, G, B or luminance (Rec. 709)")
      ->check(CLI::IsMember({"R", "G", "B", "luminance"}))
      ->capture_default_str();
  o->panelsOption = app->add_option("--panels", o->panels,
                  "The BRDFs to draw, as a sheet's --panels: a grid's name (" + gridNames() + ") or a comma list of "
                  "measured and MODEL:METRIC fits, in order; default: " + panelList(sheetPanels()));
  app->add_option("--figures", o->figures, "Only these kinds of figure (default: all): theta_h, image_slice, albedo, polar")
      ->check(CLI::IsMember(std::vector<std::string>(plot::kPlotKinds.begin(), plot::kPlotKinds.end())))
      ->delimiter(',');
  app->add_option("--decades", o->decades,
                  "Decades the log scales span below the peak (default: down to every curve's floor)")
      ->check(CLI::Range(1, 20));
  app->add_option("--polar-scale", o->polarScale, "Radius of the polar lobes: log (decades) or linear")
      ->check(CLI::IsMember({"log", "linear"}))
      ->capture_default_str();
  return {app, [o] { return runPlot(*o); }};
}

}  // namespace glossy::cli
