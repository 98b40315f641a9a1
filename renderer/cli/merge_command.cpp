// glossy merge: what the shards of a job array made, brought together (docs/cluster.md).
//   glossy merge fits DIR -o LIBRARY          each DIR/NAME.toml's fits put into LIBRARY/NAME.toml (other fits kept;
//                                             a published fit never replaced unless --replace)
//   glossy merge sheets DIR --csv F --json F  every sheet's error figures in one table
// The jobs are renderer/app/merge_job.h; this is their command line.
#include "renderer/app/merge_job.h"
#include "renderer/cli/command.h"

#include <memory>

namespace glossy::cli {

Command addMergeCommand(CLI::App& parent) {
  auto fitsRequest = std::make_shared<app::MergeFitsRequest>();
  auto sheetsRequest = std::make_shared<app::MergeSheetsRequest>();
  CLI::App* app = parent.add_subcommand("merge", "Bring together what the shards of a job array made (docs/cluster.md)");
  app->require_subcommand(1);
  CLI::App* fits = app->add_subcommand("fits", "Put every fit of DIR/NAME.toml (glossy fit --out-dir) into LIBRARY/NAME.toml, "
                                               "keeping the fits already there of other models and metrics; glossy's fits go beside the published ones");
  fits->add_option("dir", fitsRequest->fitsDir, "Folder of parameter files the shards wrote")->required();
  fits->add_option("-o,--output", fitsRequest->library, "Folder of the parameter files to update (created when missing)")->required();
  fits->add_flag("--replace", fitsRequest->replace, "let a file's published fit replace a different published one there (refused without)");
  CLI::App* sheets = app->add_subcommand("sheets", "Every sheet's error figures (glossy sheets -o DIR) in one CSV and/or JSON table");
  sheets->add_option("dir", sheetsRequest->sheetsDir, "Folder of sheets")->required();
  sheets->add_option("--csv", sheetsRequest->csv, "One row per panel of every sheet");
  sheets->add_option("--json", sheetsRequest->json, "One object per sheet, its panels inside");
  return {app, [fitsRequest, sheetsRequest, fits] {
            if (fits->parsed()) app::mergeFits(*fitsRequest);
            else app::mergeSheets(*sheetsRequest);
            return 0;
          }};
}

}  // namespace glossy::cli
