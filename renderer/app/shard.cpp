#include "renderer/app/shard.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/util/notes.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <optional>

namespace glossy::app {

namespace {

// An array index or size: a whole number, in [lo, 1e9].
std::optional<long long> wholeNumber(const char* text, long long lo) {
  if (!text) return std::nullopt;
  const std::optional<double> v = parseNumber(text);
  if (!v || *v != double((long long)*v) || *v < double(lo) || *v > 1e9) return std::nullopt;
  return (long long)*v;
}

long long required(const ArrayVariables& env, const char* name, long long lo, const std::string& why) {
  const char* text = env(name);
  const auto v = wholeNumber(text, lo);
  if (!v)
    throw InputError(std::string(name) + (text ? ": '" + shortened(text) + "' is not a whole number >= " + std::to_string(lo)
                                               : " is not set") + why);
  return *v;
}

Shard slurmShard(const ArrayVariables& env) {
  const std::string why = " (a Slurm array task; or pass --shard i/N)";
  const long long id = required(env, "SLURM_ARRAY_TASK_ID", 0, why), min = required(env, "SLURM_ARRAY_TASK_MIN", 0, why);
  const long long step = env("SLURM_ARRAY_TASK_STEP") ? required(env, "SLURM_ARRAY_TASK_STEP", 1, why) : 1;
  const long long count = env("SLURM_ARRAY_TASK_COUNT")
                              ? required(env, "SLURM_ARRAY_TASK_COUNT", 1, why)
                              : (required(env, "SLURM_ARRAY_TASK_MAX", min, why) - min) / step + 1;
  // A range min-max:step numbers its tasks; a list such as 1,4,9 does not say which of them this one is (nor,
  // when Slurm gives _MAX too, does it span min + (count - 1) step).
  const bool range = !env("SLURM_ARRAY_TASK_MAX") || required(env, "SLURM_ARRAY_TASK_MAX", min, why) == min + (count - 1) * step;
  if (!range || id < min || (id - min) % step != 0 || (id - min) / step >= count)
    throw InputError(formatted("SLURM_ARRAY_TASK_ID=%lld is not task k of the range %lld + %lld k, k < %lld: submit the array as "
                               "MIN-MAX[:STEP], or pass --shard i/N", id, min, step, count));
  const long long max = min + (count - 1) * step;
  return {int((id - min) / step), int(count),
          formatted("Slurm array task %lld (array %lld-%lld%s, %lld tasks)", id, min, max,
                    step > 1 ? formatted(":%lld", step).c_str() : "", count)};
}

Shard indexedShard(const ArrayVariables& env, const char* indexName, const char* countName, const char* scheduler) {
  const std::string why = std::string(" (") + scheduler + "; or pass --shard i/N)";
  const long long index = required(env, indexName, 0, why), count = required(env, countName, 1, why);
  if (index >= count)
    throw InputError(formatted("%s=%lld is not below %s=%lld", indexName, index, countName, count));
  return {int(index), int(count), formatted("%s index %lld of %lld (%s, %s)", scheduler, index, count, indexName, countName)};
}

}  // namespace

Shard shardFrom(const std::string& option, const ArrayVariables& env) {
  if (!option.empty()) {
    // Each part a whole number up to 1e9 (sscanf's %d would overflow on more digits), the whole text i/N, so
    // that "0/3/4" is refused rather than read as 0/3.
    const size_t slash = option.find('/');
    const auto part = [&](const std::string& text) {
      return text.find_first_not_of("0123456789") == std::string::npos ? wholeNumber(text.c_str(), 0) : std::nullopt;
    };
    const auto i = slash == std::string::npos ? std::nullopt : part(option.substr(0, slash));
    const auto n = slash == std::string::npos ? std::nullopt : part(option.substr(slash + 1));
    if (!i || !n || *n < 1 || *i >= *n)
      throw InputError("--shard: '" + shortened(option) + "' is not i/N with 0 <= i < N <= 1e9");
    return {int(*i), int(*n), "--shard " + option};
  }
  if (env("SLURM_ARRAY_TASK_ID")) return slurmShard(env);
  if (env("JOB_COMPLETION_INDEX")) return indexedShard(env, "JOB_COMPLETION_INDEX", "GLOSSY_SHARD_COUNT", "Kubernetes indexed Job");
  if (env("AWS_BATCH_JOB_ARRAY_INDEX"))
    return indexedShard(env, "AWS_BATCH_JOB_ARRAY_INDEX", "AWS_BATCH_JOB_ARRAY_SIZE", "AWS Batch array job");
  return {0, 1, ""};
}

Shard shardFrom(const std::string& option) {
  return shardFrom(option, [](const char* name) -> const char* { return std::getenv(name); });
}

std::vector<size_t> shardItems(std::span<const double> costs, const Shard& shard) {
  std::vector<size_t> order(costs.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return costs[a] > costs[b]; });
  // Longest first, each to the least loaded shard (the first of equals): with non-negative costs the k-th
  // item goes to one of the first k shards, so with more shards than items the rest stay empty and need
  // no entry, so a huge N costs nothing.
  std::vector<double> load(std::min(size_t(shard.count), costs.size()), 0.0);
  std::vector<size_t> mine;
  for (size_t item : order) {
    const size_t to = size_t(std::min_element(load.begin(), load.end()) - load.begin());
    load[to] += costs[item];
    if (to == size_t(shard.index)) mine.push_back(item);
  }
  std::sort(mine.begin(), mine.end());
  return mine;
}

std::vector<size_t> shardItems(std::span<const double> costs, const Shard& shard, const char* command, const char* items) {
  std::vector<size_t> mine = shardItems(costs, shard);
  double myCost = 0.0;
  for (size_t k : mine) myCost += costs[k];
  if (!shard.source.empty())
    tell(formatted("%s: shard %d/%d from %s: %zu of %zu %s, %.1f %% of the expected cost", command, shard.index, shard.count,
                   shard.source.c_str(), mine.size(), costs.size(), items,
                   100.0 * myCost / std::accumulate(costs.begin(), costs.end(), 0.0)));
  return mine;
}

}  // namespace glossy::app
