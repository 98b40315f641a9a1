// Which part of a batch a process does (renderer/app/shard.h): --shard, the array schedulers' variables,
// their malformed forms, and the split by cost.
#include "renderer/app/shard.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <chrono>
#include <map>
#include <numeric>
#include <set>

using namespace glossy;
using namespace glossy::test;
using namespace glossy::app;

namespace {

ArrayVariables envOf(std::map<std::string, std::string> vars) {
  auto held = std::make_shared<std::map<std::string, std::string>>(std::move(vars));
  return [held](const char* name) -> const char* {
    const auto it = held->find(name);
    return it == held->end() ? nullptr : it->second.c_str();
  };
}

}  // namespace

TEST(Shard, TheOptionWinsOverTheEnvironment) {
  const Shard s = shardFrom("2/5", envOf({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}));
  EXPECT_EQ(s.index, 2);
  EXPECT_EQ(s.count, 5);
  EXPECT_EQ(s.source, "--shard 2/5");
  const Shard none = shardFrom("", envOf({}));
  EXPECT_EQ(none.count, 1);
  EXPECT_TRUE(none.source.empty());
}

TEST(Shard, SlurmArraysByRangeAndStep) {
  Shard s = shardFrom("", envOf({{"SLURM_ARRAY_TASK_ID", "3"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_MAX", "15"},
                                 {"SLURM_ARRAY_TASK_COUNT", "16"}, {"SLURM_ARRAY_TASK_STEP", "1"}}));
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 16);
  EXPECT_EQ(s.source, "Slurm array task 3 (array 0-15, 16 tasks)");
  // --array=4-34:2 (16 tasks); without _COUNT, from _MAX and _STEP.
  s = shardFrom("", envOf({{"SLURM_ARRAY_TASK_ID", "10"}, {"SLURM_ARRAY_TASK_MIN", "4"}, {"SLURM_ARRAY_TASK_MAX", "34"},
                           {"SLURM_ARRAY_TASK_STEP", "2"}}));
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 16);
  EXPECT_EQ(s.source, "Slurm array task 10 (array 4-34:2, 16 tasks)");
}

TEST(Shard, KubernetesAndAwsBatch) {
  Shard s = shardFrom("", envOf({{"JOB_COMPLETION_INDEX", "7"}, {"GLOSSY_SHARD_COUNT", "16"}}));
  EXPECT_EQ(s.index, 7);
  EXPECT_EQ(s.count, 16);
  EXPECT_NE(s.source.find("Kubernetes"), std::string::npos);
  s = shardFrom("", envOf({{"AWS_BATCH_JOB_ARRAY_INDEX", "0"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "2"}}));
  EXPECT_EQ(s.index, 0);
  EXPECT_EQ(s.count, 2);
  EXPECT_NE(s.source.find("AWS Batch"), std::string::npos);
}

TEST(Shard, MalformedArraysAreInputErrorsNamingTheVariable) {
  const auto error = [](std::map<std::string, std::string> vars) {
    return expectInputError([&] { shardFrom("", envOf(vars)); });
  };
  EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "3"}}).find("SLURM_ARRAY_TASK_MIN is not set"), std::string::npos);
  EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "x"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_COUNT", "2"}}).find("SLURM_ARRAY_TASK_ID: 'x'"),
            std::string::npos);
  // --array=1,4,9: Slurm gives MIN 1, MAX 9, COUNT 3: every task is refused, task 1 too.
  EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "9"},
                   {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_ARRAY_TASK_STEP", "1"}})
                .find("MIN-MAX[:STEP]"),
            std::string::npos);
  EXPECT_NE(error({{"SLURM_ARRAY_TASK_ID", "4"}, {"SLURM_ARRAY_TASK_MIN", "1"}, {"SLURM_ARRAY_TASK_MAX", "9"},
                   {"SLURM_ARRAY_TASK_COUNT", "3"}, {"SLURM_ARRAY_TASK_STEP", "1"}})
                .find("MIN-MAX[:STEP]"),
            std::string::npos);
  EXPECT_NE(error({{"JOB_COMPLETION_INDEX", "2"}}).find("GLOSSY_SHARD_COUNT is not set"), std::string::npos);
  EXPECT_NE(error({{"AWS_BATCH_JOB_ARRAY_INDEX", "5"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "5"}}).find("is not below"), std::string::npos);
  EXPECT_NE(error({{"AWS_BATCH_JOB_ARRAY_INDEX", "-1"}, {"AWS_BATCH_JOB_ARRAY_SIZE", "5"}}).find("AWS_BATCH_JOB_ARRAY_INDEX"),
            std::string::npos);
  EXPECT_NE(expectInputError([] { shardFrom("0/3/4", envOf({})); }).find("--shard"), std::string::npos);
}

TEST(Shard, EveryItemGoesToExactlyOneShardAndCostsBalance) {
  // 100 sheets, six of them with a measured panel (3 × the cost of an analytic one), in name order among
  // the others: by position alone, 16 shards would put two of the six in one shard.
  std::vector<double> costs(100, 6.0);
  for (size_t k : {0, 16, 32, 48, 64, 80}) costs[k] = 9.0;
  for (int count : {1, 3, 16, 100, 130}) {
    std::multiset<size_t> seen;
    double most = 0.0, least = 1e300;
    for (int i = 0; i < count; ++i) {
      const std::vector<size_t> mine = shardItems(costs, {i, count, "test"});
      EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
      double load = 0.0;
      for (size_t k : mine) seen.insert(k), load += costs[k];
      most = std::max(most, load), least = std::min(least, load);
    }
    EXPECT_EQ(seen.size(), costs.size()) << count;
    EXPECT_EQ(std::set<size_t>(seen.begin(), seen.end()).size(), costs.size()) << count << ": an item in two shards";
    // Longest first onto the least loaded: no shard exceeds another by more than the largest item.
    EXPECT_LE(most - least, 9.0) << count;
  }
  // The six expensive items land in six different shards of 16.
  std::set<int> shardsOfMeasured;
  for (int i = 0; i < 16; ++i)
    for (size_t k : shardItems(costs, {i, 16, "test"}))
      if (costs[k] == 9.0) {
        EXPECT_TRUE(shardsOfMeasured.insert(i).second) << "shard " << i;
      }
}

// More shards than items: every item its own shard, the split the same as with a load for every shard, and
// no cost for the shards that get nothing.
TEST(Shard, ManyMoreShardsThanItemsCostNothing) {
  const std::vector<double> costs = {6.0, 9.0, 6.0, 2.5, 9.0};
  // Longest first onto the first least-loaded shard: 1 → 0, 4 → 1, 0 → 2, 2 → 3, 3 → 4.
  const std::vector<size_t> expected[] = {{1}, {4}, {0}, {2}, {3}};
  for (int count : {5, 7, 1000, 1000000000}) {
    for (int i = 0; i < 5; ++i) EXPECT_EQ(shardItems(costs, {i, count, "test"}), expected[i]) << count;
    const auto start = std::chrono::steady_clock::now();
    EXPECT_TRUE(shardItems(costs, {count - 1, count, "test"}).empty() || count == 5);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0) << count;
  }
  const Shard s = shardFrom("999999999/1000000000", envOf({}));
  EXPECT_EQ(s.index, 999999999);
  EXPECT_EQ(s.count, 1000000000);
  EXPECT_TRUE(shardItems(costs, s).empty());
  // Beyond int: refused, not wrapped.
  for (const char* bad : {"1/99999999999", "99999999999/1", "1/1000000001", "-1/3", "+1/3", "1/", "/3", " 1/3"})
    EXPECT_NE(expectInputError([&] { shardFrom(bad, envOf({})); }).find("--shard"), std::string::npos) << bad;
}
