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

// The study of one run, in the order it goes: the study file and everything it names checked, every sheet
// planned (all of them, not just this shard's: the other shards write to the same folder), the scenes' and
// lightings' inputs known; then this run's sheets rendered; then, when every sheet is complete, the
// analysis.
class Study {
 public:
  explicit Study(const StudyRequest& o) : o_(o), file_(loadStudyFile(o.file, materialLibraryDir())), plan_(file_.plan), out_(o.out) {
    job_ = file_.job;
    job_.merlDir = o.merlDir;
    if (o.threads) job_.settings.threads = *o.threads;
    job_.settings.control = o.control;
    job_.settings.progress = false;
    job_.settings.passLines = true;
    checkOutputFolder(o.out, o.outName);
    // The plan this run renders and analyses, held here: never read back from OUT (study_folder.h).
    study::checkStudyFolder(out_, plan_);
    try {
      checkImageMemory(job_.settings.width, job_.settings.height, int(job_.settings.panels.size()), kSheetBytesPerPanelPixel);
    } catch (const InputError& e) {
      throw InputError(o.file + ": settings: " + e.what());  // the study file's keys, not the command line's
    }
    if (o.analyseOnly && !o.shard.empty()) throw InputError("--analyse: analyses the whole study, not a shard (drop --shard)");
    shard_ = o.analyseOnly ? Shard{} : shardFrom(o.shard);
    planSheets();
    loadInputs();
  }

  // The analysis's cost, said before the sheets: a million resamples would otherwise be a silent hour at the
  // end of the run.
  double analysisSeconds() const {
    const auto& panels = job_.settings.panels;
    const size_t models = size_t(std::count_if(panels.begin(), panels.end(), [](const SheetPanel& p) { return !p.fit.empty(); }));
    const double seconds = study::expectedAnalysisSeconds(file_.resamples, plan_.materials.size(), models);
    if (shard_.source.empty() && seconds >= 60.0)
      tell(formatted("glossy study: the analysis will take about %s (analysis.resamples = %d over %zu materials and %zu models); "
                     "fewer resamples make it quicker", durationText(seconds).c_str(), file_.resamples, plan_.materials.size(), models));
    return seconds;
  }

  // This run's sheets (its shard's), each rendered unless complete; how many another run holds.
  size_t renderMine() {
    const std::vector<size_t> mine = shardItems(costs_, shard_, "glossy study", "sheets");
    // The plan, so that the sheets read back into rows with nothing but OUT (every run writes the same
    // bytes), and the folder's marker: from here, a run of another study is refused.
    study::claimStudyFolder(out_, plan_);
    if (o_.analyseOnly) return 0;
    std::vector<double> myCosts;
    for (size_t k : mine) myCosts.push_back(costs_[k]);
    const size_t busy = renderBatch(
        myCosts, [&](size_t n) { return items_[mine[n]].tag; },
        [&](size_t n, const std::string& tag) {
          const StudyItem& item = items_[mine[n]];
          return renderBatchSheet(inputsOf(item), [&]() -> const Stage& { return stageOf(item); }, plan_.materials[item.material].file,
                                  jobOf(item), item.exr, tag);
        },
        "glossy study", o_.out);
    stage_.reset();
    return busy;
  }

  bool isShard() const { return !shard_.source.empty(); }
  size_t sheets() const { return items_.size(); }
  fs::path analysisFolder() const { return out_ / study::kAnalysisFolder; }

  // The analysis stands on every sheet, each complete with this study's settings: how many are not, and
  // why the first is not.
  size_t incomplete(std::string& first) const {
    size_t missing = 0;
    for (const StudyItem& item : items_) {
      const std::string why =
          whyIncomplete(item.exr, sheetSettings(materials_[item.material], inputsOf(item), jobOf(item), ""), job_.settings);
      if (!why.empty() && missing++ == 0) first = item.tag + ": " + why;
    }
    return missing;
  }

  // The sheets read back into rows and analysed into OUT/analysis, written whole: into a fresh folder, then
  // swapped in, so that it is always one run's — no file of an earlier run left beside this one's (a
  // perceptual.svg from before the perceptual data was dropped), none of this run's beside an earlier one's
  // if it fails half-way. Analyses of one folder take turns.
  StudyRun analyse(double expectedSeconds) const {
    const std::vector<study::StudyRow> rows = study::readStudyRows(out_, plan_);
    study::AnalysisOptions analysis;
    analysis.seed = job_.settings.seed;
    analysis.resamples = file_.resamples;
    analysis.perceptualDir = plan_.perceptualDir;
    analysis.referenceModel = file_.referenceModel;
    analysis.provenance = provenanceOf(file_, job_, materials_, environments_, sceneDigests_);
    const auto start = std::chrono::steady_clock::now();
    analysis.progress = [&](int step, int steps, const std::string& what) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      tell(formatted("glossy study: analysis %d/%d: %s (%.0f s elapsed, about %s in all)", step, steps, what.c_str(), elapsed,
                     durationText(expectedSeconds).c_str()));
    };
    const fs::path folder = analysisFolder();
    const OutputLock lock(folder, o_.outName, OutputLock::Busy::Wait);
    checkWriteInside(out_, folder, o_.outName);
    FreshFolder fresh(folder);
    const study::AnalysisResult result = study::analyseStudy(rows, analysis, fresh.path());
    fresh.replaceTarget();
    tell(formatted("glossy study: %zu rows of %zu sheets analysed into %s (%zu files)", rows.size(), items_.size(), folder.c_str(),
                   result.files.size()));
    StudyRun run;
    run.summary = result.summary;
    run.rows = rows.size();
    run.files = result.files.size();
    return run;
  }

 private:
  // Every sheet, its cost and its place, checked before any work.
  void planSheets() {
    for (const study::PlannedMaterial& m : plan_.materials) materials_.push_back(loadMaterialFile(m.file));
    // The figures the analysis ranks by are against the measured panel: without any material's measured
    // data, every row would be skipped once every sheet had rendered.
    if (std::none_of(materials_.begin(), materials_.end(),
                     [&](const MaterialFile& m) { return resolveMeasured(m, job_.merlDir).has_value(); }))
      throw InputError(o_.file + ": materials: none has its measured data here (MERL tables: --merl-dir or $GLOSSY_MERL_DIR): no "
                                 "sheet could measure a model");
    for (size_t s = 0; s < plan_.scenes.size(); ++s)
      for (size_t l = 0; l < plan_.lightings.size(); ++l)
        for (size_t m = 0; m < plan_.materials.size(); ++m) {
          const fs::path relative = study::sheetPath(plan_.scenes[s], plan_.lightings[l], plan_.materials[m].name);
          std::error_code ec;
          for (const char* extension : {".exr", ".png"}) {
            const fs::path p = (out_ / relative).replace_extension(extension);
            checkWriteInside(out_, p, o_.outName);  // OUT/sheets/SCENE/LIGHTING a symlink out of OUT: refused, not followed
            if (fs::exists(p, ec) && !fs::is_regular_file(p, ec))
              throw InputError(p.string() + ": is in the way of a sheet of the study (not a file)");
          }
          items_.push_back({s, l, m, out_ / relative, relative.generic_string()});
          costs_.push_back(sheetCost(materials_[m], job_));
        }
    const fs::path folder = analysisFolder();
    checkWriteInside(out_, folder, o_.outName);
    if (std::error_code ec; fs::exists(fs::symlink_status(folder, ec)) && !fs::is_directory(folder, ec))
      throw InputError(folder.string() + ": is in the way of the study's analysis (not a folder)");
  }

  // Each scene and lighting is checked here, loaded once and let go: a missing map, a bad scene or camera
  // fails before any sheet, and what the sheets record of them (SceneOptions::inputs) is known without
  // holding a scene and an environment per pair — a study of many lightings would not fit in memory.
  void loadInputs() {
    inputs_.resize(plan_.scenes.size() * plan_.lightings.size());
    std::vector<SceneDescription> scenes;  // each one's file and digest, not its geometry
    for (size_t s = 0; s < plan_.scenes.size(); ++s) {
      SceneDescription scene = loadGltf(file_.sceneOptions(s, 0).scenePath());
      (void)file_.sceneOptions(s, 0).cameraOf(scene, aspect());
      scenes.push_back({scene.source, scene.digest, {}, {}, {}, {}});
      sceneDigests_.push_back(scene.digest);
    }
    for (size_t l = 0; l < plan_.lightings.size(); ++l) {
      const Environment environment = file_.sceneOptions(0, l).environment();
      environments_.push_back(environment.description());
      for (size_t s = 0; s < plan_.scenes.size(); ++s)
        inputs_[s * plan_.lightings.size() + l] = file_.sceneOptions(s, l).inputs(scenes[s], environment);
    }
  }

  double aspect() const { return double(job_.settings.width) / double(job_.settings.height); }
  size_t pairOf(const StudyItem& item) const { return item.scene * plan_.lightings.size() + item.lighting; }
  const std::string& inputsOf(const StudyItem& item) const { return inputs_[pairOf(item)]; }
  SheetJob jobOf(const StudyItem& item) const {
    SheetJob sheetJob = job_;
    sheetJob.scene = file_.sceneOptions(item.scene, item.lighting);
    return sheetJob;
  }
  // The stage of the sheet at hand, built when it comes and let go when the next sheet wants another: a
  // shard's sheets come in the plan's order, so each pair's is built once per run.
  const Stage& stageOf(const StudyItem& item) {
    if (const size_t pair = pairOf(item); pair != stagePair_) {
      stage_.reset();
      stage_ = std::make_unique<Stage>(file_.sceneOptions(item.scene, item.lighting), aspect());
      stagePair_ = pair;
    }
    return *stage_;
  }

  const StudyRequest& o_;
  const StudyFile file_;
  const study::StudyPlan& plan_;
  const fs::path out_;
  SheetJob job_;
  Shard shard_;
  std::vector<MaterialFile> materials_;
  std::vector<StudyItem> items_;
  std::vector<double> costs_;
  std::vector<std::string> inputs_;                      // per (scene, lighting): SceneOptions::inputs
  std::vector<std::string> environments_, sceneDigests_;  // for the results' provenance
  std::unique_ptr<Stage> stage_;
  size_t stagePair_ = SIZE_MAX;
};

}  // namespace

StudyRun runStudy(const StudyRequest& o) {
  Study study(o);
  const double analysisSeconds = study.analysisSeconds();
  const size_t busy = study.renderMine();
  StudyRun run;
  if (busy > 0) {
    tell(formatted("glossy study: %zu sheets left to the other run writing them; run again to check them and analyse", busy));
    run.ended = StudyRun::Ended::Busy;
  } else if (study.isShard()) {
    tell(formatted("glossy study: shard done; once every shard is, analyse: glossy study %s -o %s --analyse", o.file.c_str(),
                   o.out.c_str()));
    run.ended = StudyRun::Ended::ShardDone;
  } else if (std::string first; const size_t missing = study.incomplete(first)) {
    tell(formatted("glossy study: %zu of %zu sheets are not complete (%s): render them first (glossy study %s -o %s)", missing,
                   study.sheets(), first.c_str(), o.file.c_str(), o.out.c_str()));
    run.ended = StudyRun::Ended::Incomplete;
  } else {
    run = study.analyse(analysisSeconds);
  }
  run.sheets = study.sheets();
  run.analysisFolder = study.analysisFolder();
  return run;
}

}  // namespace glossy::app
