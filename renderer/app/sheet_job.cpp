#include "renderer/app/sheet_job.h"

#include "renderer/util/digest.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"
#include "materials/core/text.h"
#include "materials/models/registry.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/option_specs.h"
#include "renderer/app/render_job.h"
#include "renderer/app/sheet_resume.h"
#include "renderer/scene/material_binding.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <optional>

namespace glossy::app {

namespace {

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The measured data of a material: --measured, else the file's `measured` under --merl-dir, $GLOSSY_MERL_DIR
// or the working folder, else the network embedded beside the material file (resolveMeasured); the note
// says which. Returns null with a note saying where to get the data when there is none.
std::shared_ptr<const MerlTable> measuredOf(const MaterialFile& m, const SheetJob& o, const std::string& explicitPath,
                                            std::string& note) {
  const std::optional<std::filesystem::path> path = explicitPath.empty()
                                                        ? resolveMeasured(m, o.merlDir)
                                                        : findMeasured(explicitPath, o.merlDir);
  if (!path) {
    note = m.measured.empty() ? "the material names no measured data"
                              : "no " + m.measured + " in --merl-dir or $GLOSSY_MERL_DIR: get the MERL BRDF database "
                                "(Matusik et al. 2003) and point --merl-dir at it";
    return nullptr;
  }
  note = measuredLabel(*path);
  return loadMeasured(*path);
}

// The file measured data at `path` is read from: MerlTable::load reads NAME.binary.xz for an absent
// NAME.binary.
std::filesystem::path measuredFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) || path.extension() == ".xz") return path;
  const std::filesystem::path xz = path.string() + ".xz";
  return std::filesystem::exists(xz, ec) ? xz : path;
}

}  // namespace

void applyPassLimits(SheetSettings& s, bool sppGiven) {
  if (sppGiven || (s.targetError <= 0.0 && s.secondsPerPanel <= 0.0)) return;
  s.spp = s.secondsPerPanel > 0.0 ? 1 << 24 : kTargetErrorSppCap;
}

std::string sheetSettings(const MaterialFile& m, const std::string& stageInputs, const SheetJob& o, const std::string& explicitMeasured) {
  const std::optional<std::filesystem::path> measured = explicitMeasured.empty()
                                                            ? resolveMeasured(m, o.merlDir)
                                                            : std::optional(std::filesystem::path(explicitMeasured));
  using namespace options;
  const SheetSettings& s = o.settings;
  // Each option's part as the table names it: KEY=VALUE.
  const auto part = [](const OptionSpec& spec, const std::string& value) { return "; " + std::string(spec.resumeKey) + "=" + value; };
  return stageInputs + part(kSheetSpp, std::to_string(s.spp)) + part(kTime, formatted("%.17g", s.secondsPerPanel)) +
         part(kTargetError, formatted("%.17g", s.targetError)) + part(kSheetWidth, std::to_string(s.width) + "x" + std::to_string(s.height)) +
         part(kSeed, std::to_string(s.seed)) + part(kMaxDepth, std::to_string(s.maxDepth)) +
         part(kLightSamples, std::to_string(s.lightSamples)) + "; panels=" + panelList(s.panels) + "; half=" + (o.half ? "1" : "0") +
         part(kExposure, formatted("%.17g", o.exposure)) +
         "; measured=" + (measured ? measured->string() + "@" + fileDigest(measuredFile(*measured), "measured data") : std::string("none")) + "; material=" + m.path.filename().string() + "@" +
         contentDigest(m.path) + "; version=" + GLOSSY_VERSION + "; format=" + std::to_string(kSheetFormat);
}

namespace {

std::vector<ImageAttribute> sheetMetadata(const MaterialFile& m, const Stage& stage, const SheetJob& o, const Sheet& sheet,
                                          double seconds, const std::string& explicitMeasured) {
  std::vector<Fit> fits;  // their choices are recorded as render's are for its binding
  for (const PanelRender& p : sheet.panels)
    if (const Fit* fit = p.empty || p.panel.fit.empty() ? nullptr : m.find(FitId::parse(p.panel.fit, m.path.string()))) fits.push_back(*fit);
  std::vector<ImageAttribute> metadata =
      madeWith(o.settings, stage.description.source.string(), stage.environment.description(), sheet.droppedSamples, seconds);
  metadata.insert(metadata.end(),
                  {{"glossy:material", m.path.string()},
                   {"glossy:materialName", m.name},  // what the report names the material by, whatever the file is called
                   {"glossy:fit", std::string("sheet")},
                   {"glossy:measured", sheet.measured() ? sheet.measured()->note : std::string("none: no measured panel")},
                   {std::string(options::kSheetSpp.attribute), std::to_string(sheet.spp)},
                   {std::string(options::kTime.attribute), float(o.settings.secondsPerPanel)},
                   {std::string(options::kTargetError.attribute), float(o.settings.targetError)},
                   {"glossy:widestInterval", float(std::min(sheet.widestHalfWidth, 1e30))},
                   {std::string(options::kExposure.attribute), float(o.exposure)},
                   {kSettingsAttribute, sheetSettings(m, stage, o, explicitMeasured)}});
  for (const auto& [key, value] : choiceAttributes(fits)) metadata.push_back({key, value});
  return metadata;
}

}  // namespace

MadeSheet makeMaterialSheet(const Stage& stage, const std::filesystem::path& materialPath, const SheetJob& job,
                            const std::string& explicitMeasured) {
  MadeSheet made{loadMaterialFile(materialPath), explicitMeasured, {}, 0.0};
  std::string note;
  const auto measured = measuredOf(made.material, job, explicitMeasured, note);
  flushNotes();  // the input is good: what loading it noted comes before the (long) render
  const auto start = std::chrono::steady_clock::now();
  const SheetScene scene = makeSheetScene(stage.description, stage.bvh, stage.environment, stage.camera);
  made.sheet = renderSheet(scene, made.material, measured, note, job.settings);
  made.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const SheetSettings& s = job.settings;
  if (s.targetError > 0.0 && !(made.sheet.widestHalfWidth <= s.targetError))
    glossy::note(std::isfinite(made.sheet.widestHalfWidth)
                     ? formatted("%s: stopped short of --target-error %g at %d spp: the widest interval is ±%.4g (raise --spp%s)",
                                 made.material.name.c_str(), s.targetError, made.sheet.spp, made.sheet.widestHalfWidth,
                                 s.secondsPerPanel > 0.0 ? " or --time" : ", at most 16777216, or give --time")
                     : formatted("%s: --target-error %g has no interval to aim at (no measured panel): rendered %d spp",
                                 made.material.name.c_str(), s.targetError, made.sheet.spp));
  return made;
}

void writeSheetFiles(const MadeSheet& made, const Stage& stage, const SheetJob& job, const std::filesystem::path& exr) {
  if (exr.has_parent_path()) std::filesystem::create_directories(exr.parent_path());
  const std::filesystem::path png = std::filesystem::path(exr).replace_extension(".png");
  // The PNG first: glossy sheets keeps a sheet only once its EXR, written last, is whole (sheet_resume.h).
  writeSheetPng(made.sheet, png, job.exposure, std::filesystem::exists(kFont) ? kFont : "");
  writeSheetExr(made.sheet, exr, sheetMetadata(made.material, stage, job, made.sheet, made.seconds, made.explicitMeasured),
                job.half ? PixelType::Half : PixelType::Float);
}

void makeSheetFiles(const Stage& stage, const std::filesystem::path& materialPath, const SheetJob& job,
                    const std::filesystem::path& exr, const std::string& explicitMeasured) {
  const MadeSheet made = makeMaterialSheet(stage, materialPath, job, explicitMeasured);
  writeSheetFiles(made, stage, job, exr);
  std::cout << errorTable(made.sheet) << std::flush;
  flushNotes();  // what the render and the writing noted (a target missed, values clipped), by its sheet
  tell("glossy: wrote " + exr.string() + " and " + std::filesystem::path(exr).replace_extension(".png").string() +
       formatted(" (%g s)", made.seconds));
}

BatchSheet renderBatchSheet(const std::string& stageInputs, const std::function<const Stage&()>& stage,
                            const std::filesystem::path& materialPath, const SheetJob& job, const std::filesystem::path& exr,
                            const std::string& tag) {
  std::optional<OutputLock> lock;
  try {
    lock.emplace(exr, "-o");
  } catch (const OutputBusy& e) {
    tell("glossy: " + tag + ": " + e.what() + ", skipped");
    return BatchSheet::Busy;
  }
  if (const size_t stale = removeStaleTemporaries(exr))
    tell("glossy: " + tag + ": removed " + std::to_string(stale) + " temporary files an interrupted run left");
  const std::string why = whyIncomplete(exr, sheetSettings(loadMaterialFile(materialPath), stageInputs, job, ""), job.settings);
  if (why.empty()) {
    tell("glossy: " + tag + ": complete, skipped");
    return BatchSheet::Complete;
  }
  if (std::error_code ec; std::filesystem::exists(exr, ec)) tell("glossy: " + tag + ": " + why + ", rendering it again");
  makeSheetFiles(stage(), materialPath, job, exr, "");
  return BatchSheet::Rendered;
}

size_t renderBatch(const std::vector<double>& costs, const std::function<std::string(size_t)>& name,
                   const std::function<BatchSheet(size_t, const std::string&)>& sheet, const char* who, const std::string& folder) {
  const auto start = std::chrono::steady_clock::now();
  const size_t count = costs.size();
  size_t done = 0, skipped = 0, busy = 0;
  double left = std::accumulate(costs.begin(), costs.end(), 0.0), renderedCost = 0.0;
  for (size_t k = 0; k < count; ++k) {
    const std::string tag = formatted("[%zu/%zu] %s", k + 1, count, name(k).c_str());
    const BatchSheet outcome = sheet(k, tag);
    left -= costs[k];
    busy += outcome == BatchSheet::Busy;
    skipped += outcome == BatchSheet::Complete;
    if (outcome != BatchSheet::Rendered) continue;
    ++done;
    renderedCost += costs[k];
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    tell(formatted("glossy: %s done; %.0f s elapsed, about %.0f s to go", tag.c_str(), elapsed,
                   elapsed / renderedCost * std::max(left, 0.0)));
  }
  tell(formatted("%s: %zu sheets rendered, %zu already complete, in %s", who, done, skipped, folder.c_str()));
  return busy;
}

// A measured panel, with its table's loading, its sampler and the error figures it brings, costs about
// kMeasuredPanelCost analytic panels (measured in docs/cluster.md, "Expected cost").
constexpr double kMeasuredPanelCost = 2.5;

double sheetCost(const MaterialFile& m, const SheetJob& job) {
  double cost = 0.0;
  for (const SheetPanel& p : job.settings.panels)
    if (p.fit.empty() ? resolveMeasured(m, job.merlDir).has_value()
                      : m.find(FitId::parse(p.fit, m.path.string())) != nullptr)
      cost += p.fit.empty() ? kMeasuredPanelCost : 1.0;
  return std::max(cost, 1.0);  // an empty sheet still costs its scene and files
}

}  // namespace glossy::app
