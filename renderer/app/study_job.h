// A study without the command line: every (material, lighting, scene) sheet of a study file rendered into one
// folder — resumable, sharded — then read back into rows and analysed (docs/study.md; the folder's layout:
// renderer/study/study_plan.h; the statistics: renderer/study/study_analysis.h). `glossy study` and the
// Python module's glossy.study both run it, so the two write the same bytes.
#pragma once

#include "renderer/util/job_control.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace glossy::app {

struct StudyRequest {
  std::string file;    // the study file (TOML), as the user named it: messages quote it
  std::string out;     // the output folder: new, empty, or an earlier run's of this study
  std::string outName = "-o";  // what messages call it: the option that gave it (Python's "output")
  std::string shard;   // "i/N": render only that shard and do not analyse; "": the job array's task, else all
  std::string merlDir;  // MERL tables (else $GLOSSY_MERL_DIR)
  std::optional<int> threads;  // unset: the study file's settings.threads
  bool analyseOnly = false;    // render nothing: analyse the sheets the shards rendered
  JobControl* control = nullptr;  // the sheet in progress stops when it is cancelled (Python's Ctrl-C)
};

struct StudyRun {
  enum class Ended {
    Analysed,    // every sheet complete, the analysis written
    ShardDone,   // this shard's sheets complete; the analysis waits for every shard (analyseOnly)
    Busy,        // some sheets are being written by another run: run again to analyse
    Incomplete,  // analyseOnly, and some sheets are not complete
  } ended = Ended::Analysed;
  std::string summary;                  // summary.md, when analysed
  std::filesystem::path analysisFolder;  // OUT/analysis
  size_t sheets = 0, rows = 0, files = 0;
};

// Checks the study file and everything it names, then renders this run's sheets and, when every sheet is
// complete, the analysis. InputError (one line naming the file or option) for bad input, before any work;
// Cancelled when `control` was cancelled during a sheet (what was complete stays, and a run resumes). Says
// how it goes on stderr ("glossy study: ..."); the summary is the caller's to print.
StudyRun runStudy(const StudyRequest& request);

}  // namespace glossy::app
