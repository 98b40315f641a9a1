#include "renderer/app/study_job.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "materials/params/material_file.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/destination.h"
#include "renderer/app/image_memory.h"
#include "renderer/app/shard.h"
#include "renderer/app/sheet_job.h"
#include "renderer/app/sheet_resume.h"
#include "renderer/app/study_file.h"
#include "renderer/output/inside_folder.h"
#include "renderer/study/study_analysis.h"
#include "renderer/study/study_folder.h"
#include "renderer/study/study_rows.h"
#include "renderer/util/data_dir.h"
#include "renderer/util/digest.h"
#include "renderer/util/fresh_folder.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>

namespace glossy::app {

namespace {

namespace fs = std::filesystem;

// One sheet of the study.
struct StudyItem {
  size_t scene, lighting, material;
  fs::path exr;  // absolute within OUT
  std::string tag;
};

// What the study's results stand on (renderer/study/study_provenance.h): the study file as read, its
// settings, each lighting and scene with the digest of its contents (`environments`: each lighting's own
// description; `sceneDigests`: each scene's), each material's measured data.
study::StudyProvenance provenanceOf(const StudyFile& file, const SheetJob& job, const std::vector<MaterialFile>& materials,
                                    const std::vector<std::string>& environments, const std::vector<std::string>& sceneDigests) {
  study::StudyProvenance p;
  p.studyFile = file.path.filename().string();
  p.studyText = file.text;
  const SheetSettings& s = job.settings;
  p.settings = {s.width, s.height, s.spp, file.sppGiven, s.secondsPerPanel, s.targetError, s.seed, s.maxDepth, s.lightSamples,
                s.bsdfSamples, job.exposure, panelList(s.panels), job.half, file.resamples, file.referenceModel};
  for (size_t l = 0; l < file.lightings.size(); ++l) {
    const StudyLighting& lighting = file.lightings[l];
    study::LightingProvenance lp;
    lp.name = lighting.name;
    lp.kind = !lighting.env.empty() ? "map" : (!lighting.envConstant.empty() ? "constant" : "sky");
    lp.description = environments[l];
    if (!lighting.env.empty()) {
      lp.map = fs::path(lighting.env).filename().string();
      lp.digest = fileDigest(lighting.env, "environment map");
    }
    lp.rotate = lighting.rotate;
    p.lightings.push_back(lp);
  }
  for (size_t k = 0; k < file.scenes.size(); ++k) {
    const StudyScene& scene = file.scenes[k];
    p.scenes.push_back({scene.name, scene.builtin, fs::path(scene.gltf).filename().string(), scene.camera, sceneDigests[k]});
  }
  for (size_t m = 0; m < file.plan.materials.size(); ++m) {
    study::MaterialProvenance mp{file.plan.materials[m].name, file.plan.materials[m].database, "none", "", ""};
    if (const auto path = resolveMeasured(materials[m], job.merlDir)) {
      mp.measuredSource = measuredDatabase(*path);
      mp.measured = mp.measuredSource.find("(NBRDF reconstruction)") != std::string::npos ? "NBRDF reconstruction" : "MERL table";
      std::error_code ec;
      // MerlTable::load reads NAME.binary.xz for an absent NAME.binary, as the sheets' settings record it.
      const fs::path data = fs::exists(*path, ec) || path->extension() == ".xz" ? *path : fs::path(path->string() + ".xz");
      mp.measuredDigest = fileDigest(data, "measured data");
    }
    p.materials.push_back(mp);
  }
  return p;
}

// "40 s", "12 min", "3.5 h".
std::string durationText(double seconds) {
  if (seconds < 90.0) return formatted("%.0f s", std::max(seconds, 1.0));
  if (seconds < 5400.0) return formatted("%.0f min", seconds / 60.0);
  return formatted("%.1f h", seconds / 3600.0);
}

}  // namespace

StudyRun runStudy(const StudyRequest& o) {
  const StudyFile file = loadStudyFile(o.file, materialLibraryDir());
  SheetJob job = file.job;
  job.merlDir = o.merlDir;
  if (o.threads) job.settings.threads = *o.threads;
  job.settings.control = o.control;
  job.settings.progress = false;
  job.settings.passLines = true;
  checkOutputFolder(o.out, o.outName);
  const fs::path out = o.out;
  // The plan this run renders and analyses, held here: never read back from OUT (study_folder.h).
  const study::StudyPlan& plan = file.plan;
  study::checkStudyFolder(out, plan);
  try {
    checkImageMemory(job.settings.width, job.settings.height, int(job.settings.panels.size()), kSheetBytesPerPanelPixel);
  } catch (const InputError& e) {
    throw InputError(o.file + ": settings: " + e.what());  // the study file's keys, not the command line's
  }
  if (o.analyseOnly && !o.shard.empty()) throw InputError("--analyse: analyses the whole study, not a shard (drop --shard)");
  const Shard shard = o.analyseOnly ? Shard{} : shardFrom(o.shard);

  // Every sheet, its cost and its place, checked before any work; all of them, not just this shard's: the
  // other shards write to the same folder.
  std::vector<MaterialFile> materials;
  for (const study::PlannedMaterial& m : plan.materials) materials.push_back(loadMaterialFile(m.file));
  // The figures the analysis ranks by are against the measured panel: without any material's measured
  // data, every row would be skipped once every sheet had rendered.
  if (std::none_of(materials.begin(), materials.end(),
                   [&](const MaterialFile& m) { return resolveMeasured(m, job.merlDir).has_value(); }))
    throw InputError(o.file + ": materials: none has its measured data here (MERL tables: --merl-dir or $GLOSSY_MERL_DIR): no sheet "
                              "could measure a model");
  std::vector<StudyItem> items;
  std::vector<double> costs;
  for (size_t s = 0; s < plan.scenes.size(); ++s)
    for (size_t l = 0; l < plan.lightings.size(); ++l)
      for (size_t m = 0; m < plan.materials.size(); ++m) {
        const fs::path relative = study::sheetPath(plan.scenes[s], plan.lightings[l], plan.materials[m].name);
        std::error_code ec;
        for (const char* extension : {".exr", ".png"}) {
          const fs::path p = (out / relative).replace_extension(extension);
          checkWriteInside(out, p, o.outName);  // OUT/sheets/SCENE/LIGHTING a symlink out of OUT: refused, not followed
          if (fs::exists(p, ec) && !fs::is_regular_file(p, ec))
            throw InputError(p.string() + ": is in the way of a sheet of the study (not a file)");
        }
        items.push_back({s, l, m, out / relative, relative.generic_string()});
        costs.push_back(sheetCost(materials[m], job));
      }
  const fs::path analysisFolder = out / study::kAnalysisFolder;
  checkWriteInside(out, analysisFolder, o.outName);
  if (std::error_code ec; fs::exists(fs::symlink_status(analysisFolder, ec)) && !fs::is_directory(analysisFolder, ec))
    throw InputError(analysisFolder.string() + ": is in the way of the study's analysis (not a folder)");
  // Each scene and lighting is checked here, loaded once and let go: a missing map, a bad scene or camera
  // fails before any sheet, and what the sheets record of them (SceneOptions::inputs) is known without
  // holding a scene and an environment per pair — a study of many lightings would not fit in memory.
  const double aspect = double(job.settings.width) / double(job.settings.height);
  std::vector<std::string> inputs(plan.scenes.size() * plan.lightings.size());
  std::vector<std::string> environments, sceneDigests;  // for the results' provenance
  {
    std::vector<SceneDescription> scenes;  // each one's file and digest, not its geometry
    for (size_t s = 0; s < plan.scenes.size(); ++s) {
      SceneDescription scene = loadGltf(file.sceneOptions(s, 0).scenePath());
      (void)file.sceneOptions(s, 0).cameraOf(scene, aspect);
      scenes.push_back({scene.source, scene.digest, {}, {}, {}, {}});
      sceneDigests.push_back(scene.digest);
    }
    for (size_t l = 0; l < plan.lightings.size(); ++l) {
      const Environment environment = file.sceneOptions(0, l).environment();
      environments.push_back(environment.description());
      for (size_t s = 0; s < plan.scenes.size(); ++s)
        inputs[s * plan.lightings.size() + l] = file.sceneOptions(s, l).inputs(scenes[s], environment);
    }
  }
  const auto inputsOf = [&](const StudyItem& item) -> const std::string& { return inputs[item.scene * plan.lightings.size() + item.lighting]; };
  // The stage of the sheet at hand, built when it comes and let go when the next sheet wants another: a
  // shard's sheets come in the plan's order, so each pair's is built once per run.
  std::unique_ptr<Stage> stage;
  size_t stagePair = SIZE_MAX;
  const auto stageOf = [&](const StudyItem& item) -> const Stage& {
    if (const size_t pair = item.scene * plan.lightings.size() + item.lighting; pair != stagePair) {
      stage.reset();
      stage = std::make_unique<Stage>(file.sceneOptions(item.scene, item.lighting), aspect);
      stagePair = pair;
    }
    return *stage;
  };
  const auto jobOf = [&](const StudyItem& item) {
    SheetJob sheetJob = job;
    sheetJob.scene = file.sceneOptions(item.scene, item.lighting);
    return sheetJob;
  };

  // The analysis's cost, said before the sheets: a million resamples would otherwise be a silent hour at
  // the end of the run.
  const size_t modelPanels = size_t(std::count_if(job.settings.panels.begin(), job.settings.panels.end(), [](const SheetPanel& p) { return !p.fit.empty(); }));
  const double analysisSeconds = study::expectedAnalysisSeconds(file.resamples, plan.materials.size(), modelPanels);
  if (shard.source.empty() && analysisSeconds >= 60.0)
    std::fprintf(stderr, "glossy study: the analysis will take about %s (analysis.resamples = %d over %zu materials and %zu models); fewer "
                         "resamples make it quicker\n", durationText(analysisSeconds).c_str(), file.resamples, plan.materials.size(), modelPanels);

  const std::vector<size_t> mine = shardItems(costs, shard, "glossy study", "sheets");

  // The plan, so that the sheets read back into rows with nothing but OUT (every run writes the same bytes),
  // and the folder's marker: from here, a run of another study is refused.
  study::claimStudyFolder(out, plan);

  std::vector<double> myCosts;
  for (size_t k : mine) myCosts.push_back(costs[k]);
  const size_t busy = o.analyseOnly ? 0 : renderBatch(
      myCosts, [&](size_t n) { return items[mine[n]].tag; },
      [&](size_t n, const std::string& tag) {
        const StudyItem& item = items[mine[n]];
        return renderBatchSheet(inputsOf(item), [&]() -> const Stage& { return stageOf(item); }, plan.materials[item.material].file,
                                jobOf(item), item.exr, tag);
      },
      "glossy study", o.out);
  stage.reset();
  StudyRun run;
  run.sheets = items.size();
  run.analysisFolder = analysisFolder;
  if (busy > 0) {
    std::fprintf(stderr, "glossy study: %zu sheets left to the other run writing them; run again to check them and analyse\n", busy);
    run.ended = StudyRun::Ended::Busy;
    return run;
  }
  if (!shard.source.empty()) {
    std::fprintf(stderr, "glossy study: shard done; once every shard is, analyse: glossy study %s -o %s --analyse\n", o.file.c_str(),
                 o.out.c_str());
    run.ended = StudyRun::Ended::ShardDone;
    return run;
  }

  // The analysis stands on every sheet, each complete with this study's settings.
  size_t missing = 0;
  std::string first;
  for (const StudyItem& item : items) {
    const std::string why = whyIncomplete(item.exr, sheetSettings(materials[item.material], inputsOf(item), jobOf(item), ""), job.settings);
    if (!why.empty() && missing++ == 0) first = item.tag + ": " + why;
  }
  if (missing > 0) {
    std::fprintf(stderr, "glossy study: %zu of %zu sheets are not complete (%s): render them first (glossy study %s -o %s)\n", missing,
                 items.size(), first.c_str(), o.file.c_str(), o.out.c_str());
    run.ended = StudyRun::Ended::Incomplete;
    return run;
  }
  const std::vector<study::StudyRow> rows = study::readStudyRows(out, plan);
  study::AnalysisOptions analysis;
  analysis.seed = job.settings.seed;
  analysis.resamples = file.resamples;
  analysis.perceptualDir = plan.perceptualDir;
  analysis.referenceModel = file.referenceModel;
  analysis.provenance = provenanceOf(file, job, materials, environments, sceneDigests);
  const auto analysisStart = std::chrono::steady_clock::now();
  analysis.progress = [&](int step, int steps, const std::string& what) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - analysisStart).count();
    std::fprintf(stderr, "glossy study: analysis %d/%d: %s (%.0f s elapsed, about %s in all)\n", step, steps, what.c_str(), elapsed,
                 durationText(analysisSeconds).c_str());
  };
  // Written whole: into a fresh folder, then swapped in, so that OUT/analysis is always one run's — no file
  // of an earlier run left beside this one's (a perceptual.svg from before the perceptual data was dropped),
  // none of this run's beside an earlier one's if it fails half-way. Analyses of one folder take turns.
  const OutputLock lock(analysisFolder, o.outName, OutputLock::Busy::Wait);
  checkWriteInside(out, analysisFolder, o.outName);
  FreshFolder fresh(analysisFolder);
  const study::AnalysisResult result = study::analyseStudy(rows, analysis, fresh.path());
  fresh.replaceTarget();
  std::fprintf(stderr, "glossy study: %zu rows of %zu sheets analysed into %s (%zu files)\n", rows.size(), items.size(),
               analysisFolder.c_str(), result.files.size());
  run.summary = result.summary;
  run.rows = rows.size();
  run.files = result.files.size();
  return run;
}

}  // namespace glossy::app
