// glossy report: a static, offline HTML site over a folder of sheets and their plots
// (renderer/report/report_site.h; docs/report.md). The job is renderer/app/report_job.h; this is its command
// line.
#include "renderer/app/report_job.h"
#include "renderer/cli/command.h"
#include "renderer/plot/plot_output.h"

#include <memory>

namespace glossy::cli {

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
  return {app, [o] {
            app::makeReport(*o);
            return 0;
          }};
}

}  // namespace glossy::cli
