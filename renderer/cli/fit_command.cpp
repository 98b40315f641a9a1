// glossy fit: fit an analytic model to a measured table under E1 or E2, writing or updating the
// material's parameter file; with --measured-dir, every model and metric for every table, resumably (that
// batch is renderer/app/fit_job.h).
#include "materials/core/input_error.h"
#include "materials/fitting/fitter.h"
#include "materials/models/registry.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/destination.h"
#include "renderer/app/fit_job.h"
#include "renderer/app/fit_output.h"
#include "renderer/cli/command.h"
#include "renderer/cli/output.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

#include <iostream>
#include <optional>

namespace glossy::cli {

namespace {

struct FitOptions {
  std::string measured, merlDir, output, measuredDir, outDir, shard;
  std::vector<std::string> models, metrics;
  FitSettings settings;
  bool replace = false;
};

int runSingle(const FitOptions& o) {
  if (o.models.size() != 1 || o.metrics.size() != 1)
    throw InputError("glossy fit --measured needs one --model and one --metric (or use --measured-dir for all)");
  if (!o.output.empty()) checkOutputFile(o.output, "-o", {".toml"}, Folder::Exist);
  // Held from before the fit until the file is written: a second run into the file is refused at once.
  std::optional<OutputLock> lock;
  if (!o.output.empty()) lock.emplace(o.output, "-o");
  const std::filesystem::path tablePath = findMeasured(o.measured, o.merlDir);
  const Metric metric = parseMetric(o.metrics[0], "--metric");
  requireFittable(o.models[0]);
  // Validate the output file before the (slow) fit.
  MaterialFile material = materialForFit(o.output, tablePath);
  const auto table = loadMeasured(tablePath);
  flushNotes();  // the input is good: what loading it noted comes before the (slow) fit
  const MetricData data(*table, metric);
  FitReport report = fitModel(data, o.models[0], o.settings);
  stampGlossysFit(report.fit, tablePath);
  std::cerr << "glossy: " << tablePath.filename().string() << " " << app::describeFit(report) << "\n";
  if (o.output.empty()) {
    const std::string replaced = putGlossysFit(material, report.fit, o.replace);
    if (!replaced.empty()) std::cerr << "glossy: the fit: " << replaced << "\n";
    return writeStdout(toToml(material));
  }
  const std::string replaced = writeGlossysFit(o.output, tablePath, report.fit, o.replace);
  if (!replaced.empty()) std::cerr << "glossy: " << o.output << ": " << replaced << "\n";
  return 0;
}

}  // namespace

Command addFitCommand(CLI::App& parent) {
  auto o = std::make_shared<FitOptions>();
  CLI::App* app = parent.add_subcommand("fit", "Fit analytic models to measured MERL data under E1 or E2 (docs/fitting.md)");
  app->add_option("--measured", o->measured, "Measured data to fit: a MERL table (.binary or .binary.xz) or a .nbrdf network");
  app->add_option("--merl-dir", o->merlDir, "where to look for --measured (else $GLOSSY_MERL_DIR)");
  app->add_option("--model", o->models, "model to fit: " + fittableModelNames() + " (batch: repeatable, default all)");
  app->add_option("--metric", o->metrics, "E1 or E2 (batch: repeatable, default both)");
  app->add_option("-o,--output", o->output,
                  "material TOML to write or update: the fit goes in as MODEL:METRIC:glossy, its other fits are kept; default: stdout");
  app->add_option("--measured-dir", o->measuredDir, "batch: fit every table (or .nbrdf network) in this folder");
  app->add_option("--out-dir", o->outDir, "batch: one material TOML per table here; fits already made are skipped");
  app->add_option("--shard", o->shard,
                  "batch: i/N: only shard i (0-based) of N, the tables split by expected cost; default: the job array's "
                  "task (Slurm, Kubernetes indexed Job, AWS Batch; docs/cluster.md)");
  app->add_flag("--replace", o->replace, "also remove the published fit of the model and metric fitted (never done without it)");
  addOption(app, options::kStarts, o->settings.refinedStarts);
  addOption(app, options::kMaxIterations, o->settings.maxIterations);
  addOption(app, options::kThreads, o->settings.threads);
  auto measured = app->get_option("--measured");
  auto dir = app->get_option("--measured-dir");
  measured->excludes(dir);
  app->get_option("-o")->excludes(dir);
  app->get_option("--shard")->needs(dir);
  return {app, [o] {
            if (!o->measuredDir.empty()) {
              app::fitTables({o->measuredDir, o->outDir, o->models, o->metrics, o->shard, o->settings, o->replace});
              return 0;
            }
            if (o->measured.empty()) throw InputError("glossy fit needs --measured FILE or --measured-dir DIR");
            return runSingle(*o);
          }};
}

}  // namespace glossy::cli
