// glossy study: every (material, lighting, scene) sheet of a study file rendered into one folder — resumable,
// sharded like glossy sheets — then read back into rows and analysed (docs/study.md; the folder's layout:
// renderer/study/study_plan.h; the statistics: renderer/study/study_analysis.h).
#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/params/material_file.h"
#include "renderer/app/destination.h"
#include "renderer/app/image_memory.h"
#include "renderer/app/shard.h"
#include "renderer/app/sheet_resume.h"
#include "renderer/app/study_file.h"
#include "renderer/cli/command.h"
#include "renderer/output/inside_folder.h"
#include "renderer/study/study_analysis.h"
#include "renderer/study/study_folder.h"
#include "renderer/study/study_rows.h"
#include "renderer/util/fresh_folder.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace glossy::cli {

namespace {

namespace fs = std::filesystem;

struct StudyOptions {
  std::string file, out, shard, merlDir;
  int threads = 0;
  CLI::Option* threadsOption = nullptr;
  bool analyseOnly = false;
};

// One sheet of the study.
struct StudyItem {
  size_t scene, lighting, material;
  fs::path exr;  // absolute within OUT
  std::string tag;
};

int runStudy(const StudyOptions& o) {
  const StudyFile file = loadStudyFile(o.file, defaultMaterialsDir());
  SheetJob job = file.job;
  job.merlDir = o.merlDir;
  if (o.threadsOption->count() > 0) job.settings.threads = o.threads;
  job.settings.progress = false;
  job.settings.passLines = true;
  checkOutputFolder(o.out, "-o");
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
  std::vector<StudyItem> items;
  std::vector<double> costs;
  for (size_t s = 0; s < plan.scenes.size(); ++s)
    for (size_t l = 0; l < plan.lightings.size(); ++l)
      for (size_t m = 0; m < plan.materials.size(); ++m) {
        const fs::path relative = study::sheetPath(plan.scenes[s], plan.lightings[l], plan.materials[m].name);
        std::error_code ec;
        for (const char* extension : {".exr", ".png"}) {
          const fs::path p = (out / relative).replace_extension(extension);
          checkWriteInside(out, p, "-o");  // OUT/sheets/SCENE/LIGHTING a symlink out of OUT: refused, not followed
          if (fs::exists(p, ec) && !fs::is_regular_file(p, ec))
            throw InputError(p.string() + ": is in the way of a sheet of the study (not a file)");
        }
        items.push_back({s, l, m, out / relative, relative.generic_string()});
        costs.push_back(sheetCost(materials[m], job));
      }
  const fs::path analysisFolder = out / study::kAnalysisFolder;
  checkWriteInside(out, analysisFolder, "-o");
  if (std::error_code ec; fs::exists(fs::symlink_status(analysisFolder, ec)) && !fs::is_directory(analysisFolder, ec))
    throw InputError(analysisFolder.string() + ": is in the way of the study's analysis (not a folder)");
  // The scene and lighting of each pair, loaded once: a missing map or a bad scene fails here.
  std::vector<std::unique_ptr<Stage>> stages;
  const double aspect = double(job.settings.width) / double(job.settings.height);
  for (size_t s = 0; s < plan.scenes.size(); ++s)
    for (size_t l = 0; l < plan.lightings.size(); ++l) stages.push_back(std::make_unique<Stage>(file.sceneOptions(s, l), aspect));
  const auto stageOf = [&](const StudyItem& item) -> const Stage& { return *stages[item.scene * plan.lightings.size() + item.lighting]; };
  const auto jobOf = [&](const StudyItem& item) {
    SheetJob sheetJob = job;
    sheetJob.scene = file.sceneOptions(item.scene, item.lighting);
    return sheetJob;
  };

  const std::vector<size_t> mine = shardItems(costs, shard, "glossy study", "sheets");

  // The plan, so that the sheets read back into rows with nothing but OUT (every run writes the same bytes),
  // and the folder's marker: from here, a run of another study is refused.
  study::claimStudyFolder(out, plan);

  const size_t busy = o.analyseOnly ? 0 : renderBatch(
      mine.size(), [&](size_t n) { return items[mine[n]].tag; },
      [&](size_t n, const std::string& tag) {
        const StudyItem& item = items[mine[n]];
        return renderBatchSheet(stageOf(item), plan.materials[item.material].file, jobOf(item), item.exr, tag);
      },
      "glossy study", o.out);
  if (busy > 0) {
    std::fprintf(stderr, "glossy study: %zu sheets left to the other run writing them; run again to check them and analyse\n", busy);
    return 1;
  }
  if (!shard.source.empty()) {
    std::fprintf(stderr, "glossy study: shard done; once every shard is, analyse: glossy study %s -o %s --analyse\n", o.file.c_str(),
                 o.out.c_str());
    return 0;
  }

  // The analysis stands on every sheet, each complete with this study's settings.
  size_t missing = 0;
  std::string first;
  for (const StudyItem& item : items) {
    const std::string why = whyIncomplete(item.exr, sheetSettings(materials[item.material], stageOf(item), jobOf(item), ""), job.settings);
    if (!why.empty() && missing++ == 0) first = item.tag + ": " + why;
  }
  if (missing > 0) {
    std::fprintf(stderr, "glossy study: %zu of %zu sheets are not complete (%s): render them first (glossy study %s -o %s)\n", missing,
                 items.size(), first.c_str(), o.file.c_str(), o.out.c_str());
    return 1;
  }
  const std::vector<study::StudyRow> rows = study::readStudyRows(out, plan);
  study::AnalysisOptions analysis;
  analysis.seed = job.settings.seed;
  analysis.resamples = file.resamples;
  analysis.perceptualDir = plan.perceptualDir;
  analysis.referenceModel = file.referenceModel;
  // Written whole: into a fresh folder, then swapped in, so that OUT/analysis is always one run's — no file
  // of an earlier run left beside this one's (a perceptual.svg from before the perceptual data was dropped),
  // none of this run's beside an earlier one's if it fails half-way. Analyses of one folder take turns.
  const OutputLock lock(analysisFolder, "-o", OutputLock::Busy::Wait);
  checkWriteInside(out, analysisFolder, "-o");
  FreshFolder fresh(analysisFolder);
  const study::AnalysisResult result = study::analyseStudy(rows, analysis, fresh.path());
  fresh.replaceTarget();
  std::cout << result.summary << std::flush;
  std::fprintf(stderr, "glossy study: %zu rows of %zu sheets analysed into %s (%zu files)\n", rows.size(), items.size(),
               analysisFolder.c_str(), result.files.size());
  return 0;
}

}  // namespace

Command addStudyCommand(CLI::App& parent) {
  auto o = std::make_shared<StudyOptions>();
  CLI::App* app = parent.add_subcommand(
      "study",
      "Render every (material, lighting, scene) sheet a study file names into OUT/sheets, then analyse them into OUT/analysis "
      "(docs/study.md); sheets already complete are skipped, so an interrupted run resumes.");
  app->add_option("STUDY", o->file, "The study file (TOML; docs/study.md)")->required();
  app->add_option("-o,--output", o->out, "Output folder: new, empty, or an earlier run's of this study")->required();
  app->add_option("--shard", o->shard,
                  "i/N: render only shard i (0-based) of N, the sheets split by expected cost, and do not analyse; default: the "
                  "job array's task (Slurm, Kubernetes indexed Job, AWS Batch; docs/cluster.md)");
  app->add_flag("--analyse", o->analyseOnly, "Render nothing: analyse the sheets the shards rendered (every one must be complete)");
  // Unset, the study file's threads apply, not the table's default.
  o->threadsOption = addOption(app, options::kThreads, o->threads)
                         ->default_str("")
                         ->description("Threads (0 = all cores); unset: the study file's settings.threads, else all cores");
  app->add_option("--merl-dir", o->merlDir, "Folder with MERL tables (else $GLOSSY_MERL_DIR)");
  return {app, [o] { return runStudy(*o); }};
}

}  // namespace glossy::cli
