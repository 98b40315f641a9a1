// glossy fit's batch without the command line: every model under every metric fitted to every table of a
// folder, one material file per table, resumable (fits this version already made with these settings are
// skipped) and sharded as job arrays split it (docs/cluster.md). `glossy fit --measured-dir` and the Python
// module's glossy.fit_tables run it, so the two write the same files.
#pragma once

#include "materials/fitting/fitter.h"

#include <string>
#include <vector>

namespace glossy::app {

struct FitBatchRequest {
  std::string measuredDir;  // the tables (.binary, .binary.xz) and networks (.nbrdf); a material's .binary wins
  std::string outDir;       // one material file per table, NAME.toml, created or updated
  std::vector<std::string> models, metrics;  // empty: every fittable model; E1 and E2
  std::string shard;        // "i/N", or "": the job array's task, else all
  FitSettings settings;
  bool replace = false;     // also remove the published fit of the model and metric fitted
  // What messages call the options: the command line's, or Python's keywords.
  std::string outDirName = "--out-dir", modelName = "--model", metricName = "--metric";
};

struct FitBatchRun {
  size_t tables = 0, fits = 0, alreadyDone = 0;  // this shard's
};

// Every output file is read (and so validated) before anything is fitted: InputError naming the file or
// option for bad input. Each fit is written as soon as it is made, under the file's lock.
FitBatchRun fitTables(const FitBatchRequest& request);

// One fit as a line: "cook-torrance:E2:glossy: E2 = 0.0193 in 12.3 s (… scanned, …); kd = [...]; …".
std::string describeFit(const FitReport& report);

}  // namespace glossy::app
