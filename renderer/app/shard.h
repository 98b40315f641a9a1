// Which part of a batch (`glossy sheets`, `glossy fit --measured-dir`) this process does: --shard i/N, else
// the job array it runs in — a Slurm array task, a Kubernetes indexed Job's pod, an AWS Batch array child —
// else all of it. Every task of an array computes the same split from the same item list, so no two do
// the same item and none is left out; a resubmitted task does its own items again and resumes past those
// finished.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace glossy::app {

struct Shard {
  int index = 0, count = 1;
  std::string source;  // for the log: "--shard 3/16", "Slurm array task 7 (array 4-34:2, 16 tasks)", ...
};

// The variables an array scheduler sets, by name (getenv, or a map in tests).
using ArrayVariables = std::function<const char*(const char*)>;

// --shard i/N when `option` is not empty; else SLURM_ARRAY_TASK_ID with SLURM_ARRAY_TASK_MIN and
// SLURM_ARRAY_TASK_COUNT (or _MAX, with _STEP), JOB_COMPLETION_INDEX with GLOSSY_SHARD_COUNT (a Kubernetes
// indexed Job does not tell its pods the completions), AWS_BATCH_JOB_ARRAY_INDEX with
// AWS_BATCH_JOB_ARRAY_SIZE; else the whole batch. InputError naming the option or the variables when they
// are malformed or do not describe a regular array.
Shard shardFrom(const std::string& option, const ArrayVariables& env);
Shard shardFrom(const std::string& option);  // the process's environment

// The items of `shard`, in their order: the batch split by expected cost (longest first, each to the
// shard with least so far; ties by order), so that the measured tables and slow fits spread evenly
// rather than fall to a few shards by name.
std::vector<size_t> shardItems(std::span<const double> costs, const Shard& shard);
// The same, saying on stderr which part of the batch a shard took: "glossy sheets: shard 3/16 from --shard
// 3/16: 5 of 40 materials, 12.5 % of the expected cost" (`command`: "glossy sheets", `items`: "materials").
std::vector<size_t> shardItems(std::span<const double> costs, const Shard& shard, const char* command, const char* items);

}  // namespace glossy::app
