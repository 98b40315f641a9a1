#include "renderer/app/fit_job.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/models/registry.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/destination.h"
#include "renderer/app/fit_output.h"
#include "renderer/app/shard.h"
#include "renderer/output/inside_folder.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

#include <chrono>
#include <map>
#include <memory>
#include <sstream>

namespace glossy::app {

namespace {

std::string formatSeconds(double s) { return s < 120 ? formatted("%.1f s", s) : formatted("%.0f min", s / 60.0); }

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
double fitCost(const std::vector<std::string>& models, size_t metrics, const std::string& option) {
  double cost = 0.0;
  for (const std::string& m : models) cost += double(metrics) * requireModel(m, option).fitCost;
  return cost;
}

}  // namespace

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

FitBatchRun fitTables(const FitBatchRequest& o) {
  if (o.outDir.empty()) throw InputError("glossy fit --measured-dir needs " + o.outDirName);
  checkOutputFolder(o.outDir, o.outDirName);
  const Shard shard = shardFrom(o.shard);
  auto tables = tablesIn(o.measuredDir);
  const auto fittable = fittableModels();
  const std::vector<std::string> models = o.models.empty() ? std::vector<std::string>(fittable.begin(), fittable.end()) : o.models;
  std::vector<Metric> metrics;
  for (const std::string& m : o.metrics.empty() ? std::vector<std::string>{"E1", "E2"} : o.metrics) metrics.push_back(parseMetric(m, o.metricName));
  for (const auto& m : models) requireFittable(m, o.modelName);
  std::vector<std::filesystem::path> mine;
  for (size_t k : shardItems(std::vector<double>(tables.size(), fitCost(models, metrics.size(), o.modelName)), shard, "glossy fit", "tables"))
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
    checkWriteInside(o.outDir, out, o.outDirName);
    const MaterialFile existing = materialForFit(out, tables[t]);
    for (const auto& model : models)
      for (Metric metric : metrics) {
        const Fit* f = existing.findExact({model, std::string(metricName(metric)), std::string(FitId::kGlossy)});
        if (f && f->settings == settings) ++done;  // made by this version with these settings: resume past it
        else jobs.push_back({t, model, metric});
      }
  }
  const size_t total = done + jobs.size();
  tell(formatted("glossy fit: %zu tables, %zu fits, %zu already done", tables.size(), total, done));

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
    const OutputLock lock(out, o.outDirName);
    const std::string replaced = writeGlossysFit(out, tables[job.table], report.fit, o.replace);

    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double eta = elapsed / double(j + 1) * double(jobs.size() - j - 1);
    tell(formatted("glossy: [%zu/%zu] ", done + j + 1, total) + materialNameOf(tables[job.table]) + " " + describeFit(report) +
         "; ETA " + formatSeconds(eta));
    if (!replaced.empty()) tell("glossy: " + out.string() + ": " + replaced);
  }
  return {tables.size(), total, done};
}

}  // namespace glossy::app
