// glossy study: every (material, lighting, scene) sheet of a study file rendered into one folder — resumable,
// sharded like glossy sheets — then read back into rows and analysed (docs/study.md). The job is
// renderer/app/study_job.h; this is its command line.
#include "renderer/app/study_job.h"
#include "renderer/cli/command.h"

#include <iostream>
#include <memory>

namespace glossy::cli {

namespace {

struct StudyOptions {
  app::StudyRequest request;
  int threads = 0;
  CLI::Option* threadsOption = nullptr;
};

int runStudy(StudyOptions& o) {
  if (o.threadsOption->count() > 0) o.request.threads = o.threads;
  const app::StudyRun run = app::runStudy(o.request);
  switch (run.ended) {
    case app::StudyRun::Ended::Analysed: std::cout << run.summary << std::flush; return 0;
    case app::StudyRun::Ended::ShardDone: return 0;
    case app::StudyRun::Ended::Busy:
    case app::StudyRun::Ended::Incomplete: return 1;
  }
  return 1;
}

}  // namespace

Command addStudyCommand(CLI::App& parent) {
  auto o = std::make_shared<StudyOptions>();
  app::StudyRequest& r = o->request;
  CLI::App* app = parent.add_subcommand(
      "study",
      "Render every (material, lighting, scene) sheet a study file names into OUT/sheets, then analyse them into OUT/analysis "
      "(docs/study.md); sheets already complete are skipped, so an interrupted run resumes.");
  app->add_option("STUDY", r.file, "The study file (TOML; docs/study.md)")->required();
  app->add_option("-o,--output", r.out, "Output folder: new, empty, or an earlier run's of this study")->required();
  app->add_option("--shard", r.shard,
                  "i/N: render only shard i (0-based) of N, the sheets split by expected cost, and do not analyse; default: the "
                  "job array's task (Slurm, Kubernetes indexed Job, AWS Batch; docs/cluster.md)");
  app->add_flag("--analyse", r.analyseOnly, "Render nothing: analyse the sheets the shards rendered (every one must be complete)");
  // Unset, the study file's threads apply, not the table's default.
  o->threadsOption = addOption(app, options::kThreads, o->threads)
                         ->default_str("")
                         ->description("Threads (0 = all cores); unset: the study file's settings.threads, else all cores");
  app->add_option("--merl-dir", r.merlDir, "Folder with MERL tables (else $GLOSSY_MERL_DIR)");
  return {app, [o] { return runStudy(*o); }};
}

}  // namespace glossy::cli
