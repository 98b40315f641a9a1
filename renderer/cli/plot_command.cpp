// glossy plot: a material's BRDFs as figures — θ_h slices, image slices with the log-ratio to measured data,
// directional albedo, in-plane polar lobes — each as SVG, PNG and the CSV of its numbers, indexed by
// plots.json (renderer/plot/, docs/plots.md). The job is renderer/app/plot_job.h; this is its command line.
#include "renderer/app/plot_job.h"
#include "renderer/cli/command.h"
#include "renderer/plot/plot_output.h"
#include "renderer/sheet/comparison_grid.h"

#include <memory>

namespace glossy::cli {

namespace {

struct PlotOptions {
  app::PlotRequest request;
  std::string panels;
  CLI::Option* panelsOption = nullptr;
};

}  // namespace

Command addPlotCommand(CLI::App& parent) {
  auto o = std::make_shared<PlotOptions>();
  app::PlotRequest& r = o->request;
  CLI::App* app = parent.add_subcommand("plot",
      "Plot a material's fits and its measured data: θh slices, θh×θd image slices with the log-ratio to measured, "
      "directional albedo, in-plane polar lobes; SVG, PNG (with rsvg-convert) and the CSV of every curve, indexed by "
      "DIR/plots.json (docs/plots.md)");
  app->add_option("--material", r.material, "Material parameter file (TOML)")->required();
  app->add_option("--measured", r.measured,
                  "Measured data instead of the file's own: a MERL .binary (or .binary.xz) table or a .nbrdf network");
  app->add_option("--merl-dir", r.merlDir, "Folder with MERL tables (else $GLOSSY_MERL_DIR)");
  app->add_option("-o,--out", r.out,
                  "Output folder: created if missing; an existing one must be empty or an earlier glossy plot's, whose files "
                  "it replaces")
      ->required();
  app->add_option("--channel", r.channel, "Which channel to plot: R, G, B or luminance (Rec. 709)")
      ->check(CLI::IsMember({"R", "G", "B", "luminance"}))
      ->capture_default_str();
  o->panelsOption = app->add_option("--panels", o->panels,
                  "The BRDFs to draw, as a sheet's --panels: a grid's name (" + gridNames() + ") or a comma list of "
                  "measured and MODEL:METRIC fits, in order; default: " + panelList(sheetPanels()));
  app->add_option("--figures", r.figures, "Only these kinds of figure (default: all): theta_h, image_slice, albedo, polar")
      ->check(CLI::IsMember(std::vector<std::string>(plot::kPlotKinds.begin(), plot::kPlotKinds.end())))
      ->delimiter(',');
  app->add_option("--decades", r.decades,
                  "Decades the log scales span below the peak (default: down to every curve's floor)")
      ->check(CLI::Range(1, 20));
  app->add_option("--polar-scale", r.polarScale, "Radius of the polar lobes: log (decades) or linear")
      ->check(CLI::IsMember({"log", "linear"}))
      ->capture_default_str();
  return {app, [o] {
            if (o->panelsOption->count() > 0) o->request.panels = o->panels;
            app::makePlots(o->request);
            return 0;
          }};
}

}  // namespace glossy::cli
