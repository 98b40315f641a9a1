// glossy fit: fit an analytic model to a measured table under E1 or E2, writing or updating the
// material's parameter file; with --measured-dir, every model and metric for every table, resumably.
#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"
#include "materials/core/text.h"
#include "materials/fitting/fitter.h"
#include "materials/models/registry.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/destination.h"
#include "renderer/output/inside_folder.h"
#include "renderer/app/fit_output.h"
#include "renderer/app/shard.h"
#include "renderer/cli/command.h"
#include "renderer/cli/output.h"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

namespace glossy::cli {

namespace {

struct FitOptions {
  std::string measured, merlDir, output, measuredDir, outDir, shard;
  std::vector<std::string> models, metrics;
  FitSettings settings;
  bool replace = false;
};

std::string formatSeconds(double s) { return s < 120 ? formatted("%.1f s", s) : formatted("%.0f min", s / 60.0); }

std::string describeFit(const FitReport& r) {
  std::ostringstream s;
  s.precision(6);
  s << r.fit.id.str() << ": " << r.fit.id.metric << " = " << r.error << " in " << formatSeconds(r.seconds) << " ("
    << r.scanned << " scanned, refined starts reached";
  for (double e : r.startErrors) s << " " << e;
  s << ")";
  for (const auto& [key, value] : r.fit.params.values()) {
    s << "; " << key << " = ";
    if (auto d = std::get_if<double>(&value)) s << *d;
    if (auto c = std::get_if<Rgb>(&value)) s << "[" << c->r << ", " << c->g << ", " << c->b << "]";
  }
  return s.str();
}

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
  std::cerr << "glossy: " << tablePath.filename().string() << " " << describeFit(report) << "\n";
  if (o.output.empty()) {
    const std::string replaced = putGlossysFit(material, report.fit, o.replace);
    if (!replaced.empty()) std::cerr << "glossy: the fit: " << replaced << "\n";
    return writeStdout(toToml(material));
  }
  const std::string replaced = writeGlossysFit(o.output, tablePath, report.fit, o.replace);
  if (!replaced.empty()) std::cerr << "glossy: " << o.output << ": " << replaced << "\n";
  return 0;
}

std::vector<std::filesystem::path> tablesIn(const std::filesystem::path& dir) {
  if (std::error_code ec; !std::filesystem::is_directory(dir, ec)) throw InputError(dir.string() + ": not a directory");
  // A material's .binary wins over its .binary.xz, which wins over its .nbrdf network.
  const auto rank = [](const std::string& f) { return f.ends_with(".binary") ? 0 : f.ends_with(".binary.xz") ? 1 : 2; };
  std::map<std::string, std::filesystem::path> byName;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (!e.is_regular_file() || !(f.ends_with(".binary") || f.ends_with(".binary.xz") || f.ends_with(".nbrdf"))) continue;
    auto [it, inserted] = byName.emplace(materialNameOf(e.path()), e.path());
    if (!inserted && rank(f) < rank(it->second.filename().string())) it->second = e.path();
  }
  if (byName.empty()) throw InputError(dir.string() + ": no measured data (*.binary, *.binary.xz or *.nbrdf)");
  std::vector<std::filesystem::path> out;
  for (auto& [name, path] : byName) out.push_back(path);
  return out;
}

// What fitting a table costs, in units of a Microfacet fit under one metric at the default settings (each
// model's fitCost: docs/cluster.md, "Expected cost"). Loading is a small part of a unit for a .binary.xz and a
// .nbrdf alike, so every table costs the same.
double fitCost(const std::vector<std::string>& models, size_t metrics) {
  double cost = 0.0;
  for (const std::string& m : models) cost += double(metrics) * requireModel(m, "--model").fitCost;
  return cost;
}

int runBatch(const FitOptions& o) {
  if (o.outDir.empty()) throw InputError("glossy fit --measured-dir needs --out-dir");
  checkOutputFolder(o.outDir, "--out-dir");
  const Shard shard = shardFrom(o.shard);
  auto tables = tablesIn(o.measuredDir);
  const auto fittable = fittableModels();
  const std::vector<std::string> models = o.models.empty() ? std::vector<std::string>(fittable.begin(), fittable.end()) : o.models;
  std::vector<Metric> metrics;
  for (const std::string& m : o.metrics.empty() ? std::vector<std::string>{"E1", "E2"} : o.metrics) metrics.push_back(parseMetric(m, "--metric"));
  for (const auto& m : models) requireFittable(m);
  std::vector<std::filesystem::path> mine;
  for (size_t k : shardItems(std::vector<double>(tables.size(), fitCost(models, metrics.size())), shard, "glossy fit", "tables"))
    mine.push_back(tables[k]);
  tables = std::move(mine);
  std::filesystem::create_directories(o.outDir);
  const std::string settings = o.settings.describe();

  // Every output file is read (and so validated) before anything is fitted.
  struct Job { size_t table; std::string model; Metric metric; };
  std::vector<Job> jobs;
  size_t done = 0;
  for (size_t t = 0; t < tables.size(); ++t) {
    const std::filesystem::path out = std::filesystem::path(o.outDir) / (materialNameOf(tables[t]) + ".toml");
    checkWriteInside(o.outDir, out, "--out-dir");
    const MaterialFile existing = materialForFit(out, tables[t]);
    for (const auto& model : models)
      for (Metric metric : metrics) {
        const Fit* f = existing.findExact({model, std::string(metricName(metric)), std::string(FitId::kGlossy)});
        if (f && f->settings == settings) ++done;  // made by this version with these settings: resume past it
        else jobs.push_back({t, model, metric});
      }
  }
  const size_t total = done + jobs.size();
  std::cerr << "glossy fit: " << tables.size() << " tables, " << total << " fits, " << done << " already done\n";

  const auto t0 = std::chrono::steady_clock::now();
  std::shared_ptr<const MerlTable> table;
  size_t loaded = size_t(-1);
  std::map<Metric, std::unique_ptr<MetricData>> data;
  for (size_t j = 0; j < jobs.size(); ++j) {
    const Job& job = jobs[j];
    if (loaded != job.table) {
      table = loadMeasured(tables[job.table]);
      flushNotes();
      data.clear();
      loaded = job.table;
    }
    auto& d = data[job.metric];
    if (!d) d = std::make_unique<MetricData>(*table, job.metric);
    FitReport report = fitModel(*d, job.model, o.settings);
    stampGlossysFit(report.fit, tables[job.table]);
    const std::filesystem::path out = std::filesystem::path(o.outDir) / (materialNameOf(tables[job.table]) + ".toml");
    // After each fit, so that an interrupted batch resumes here; under the file's lock, as the tasks of a job
    // array share the folder.
    const OutputLock lock(out, "--out-dir");
    const std::string replaced = writeGlossysFit(out, tables[job.table], report.fit, o.replace);

    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double eta = elapsed / double(j + 1) * double(jobs.size() - j - 1);
    std::cerr << "glossy: [" << done + j + 1 << "/" << total << "] " << materialNameOf(tables[job.table]) << " " << describeFit(report)
              << "; ETA " << formatSeconds(eta) << "\n";
    if (!replaced.empty()) std::cerr << "glossy: " << out.string() << ": " << replaced << "\n";
  }
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
            if (!o->measuredDir.empty()) return runBatch(*o);
            if (o->measured.empty()) throw InputError("glossy fit needs --measured FILE or --measured-dir DIR");
            return runSingle(*o);
          }};
}

}  // namespace glossy::cli
