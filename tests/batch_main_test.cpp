// The batches' exit status (tests/batches/batch_main.cpp): CTest reports a batch as skipped only by its status
// 77, so a batch with a skipped case must exit 77, never 0, and one with a failure 1, whatever else ran. The
// probes are disabled: they run only in the child processes this test starts.
#include "tests/support/test_support.h"

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace glossy::test {

namespace {

int runProbes(const std::string& filter) {
  const std::string command = shellQuote(std::filesystem::read_symlink("/proc/self/exe").string()) +
                              " --gtest_also_run_disabled_tests --gtest_filter=" + shellQuote(filter) + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(DISABLED_BatchProbe, Skips) { GTEST_SKIP() << "a probe"; }
TEST(DISABLED_BatchProbe, Passes) {}
TEST(DISABLED_BatchProbe, Fails) { FAIL() << "a probe"; }

TEST(BatchMain, ABatchWithASkippedCaseIsSkippedAndOneWithAFailureFails) {
  EXPECT_EQ(runProbes("DISABLED_BatchProbe.Passes"), 0);
  EXPECT_EQ(runProbes("DISABLED_BatchProbe.Skips"), 77);
  EXPECT_EQ(runProbes("DISABLED_BatchProbe.Skips:DISABLED_BatchProbe.Passes"), 77);
  EXPECT_EQ(runProbes("DISABLED_BatchProbe.*"), 1);
}

}  // namespace glossy::test
