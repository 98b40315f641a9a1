// glossy report: a static, offline HTML site over a folder of sheets and their plots
// (renderer/report/report_site.h; docs/report.md).
#include "materials/core/text.h"
#include "renderer/util/output_lock.h"
#include "renderer/app/destination.h"
#include "renderer/cli/command.h"
#include "renderer/plot/plot_output.h"
#include "renderer/report/report_site.h"

#include <cstdio>
#include <memory>

namespace glossy::cli {

namespace {

int runReport(const report::ReportOptions& o) {
  checkOutputFolder(o.site, "-o");
  const OutputLock lock(o.site, "-o");
  const report::ReportResult r = report::writeReport(o);
  const std::string sheets = r.sheets == r.materials.size() ? formatted("%zu materials", r.sheets)
                                                             : formatted("%zu sheets of %zu materials", r.sheets, r.materials.size());
  std::fprintf(stderr, "glossy: wrote %s/index.html: %s, %zu images, %zu plot files\n", o.site.c_str(), sheets.c_str(), r.images, r.plots);
  return 0;
}

}  // namespace

Command addReportCommand(CLI::App& parent) {
  auto o = std::make_shared<report::ReportOptions>();
  o->site = "out/report";
  CLI::App* app = parent.add_subcommand("report",
      "Make a static HTML site of a folder of sheets (from glossy sheets) and optionally their plots (from glossy plot): "
      "an index of every material and model's error figures, sortable and filterable, and a page per material with its "
      "sheet, a compare view, the figures, the fit parameters and the plots. Self-contained: it works from file:// offline.");
  app->add_option("SHEETS_DIR", o->sheetsDir, "Folder of sheets: NAME.exr and NAME.png from glossy sheets, all made with the same settings; or the output "
                                        "folder of glossy study, for the study's site")
      ->required();
  app->add_option("PLOTS_DIR", o->plotsDir, "Folder of plots: PLOTS_DIR/NAME/plots.json from glossy plot (optional)");
  app->add_option("-o,--output", o->site,
                  "The site's folder: created if missing; an existing one must be empty or an earlier report, whose files it replaces")
      ->capture_default_str();
  app->add_option("--plot-kinds", o->plotKinds, "Only the plots of these kinds (theta_h, image_slice, albedo, polar); default: all")
      ->check(CLI::IsMember(std::vector<std::string>(plot::kPlotKinds.begin(), plot::kPlotKinds.end())))
      ->delimiter(',');
  app->add_flag("--plot-data,!--no-plot-data", o->plotData,
                "Also copy each plot's SVG and CSV beside its picture and link them (default: the picture alone, a lighter site)");
  return {app, [o] { return runReport(*o); }};
}

}  // namespace glossy::cli
