// glossy_tests' main. CTest runs the cases a suite (or a shard of one) at a time (add_test_batches.cmake): a
// batch in which a case skipped (its data absent, or a condition such as running as root) and none failed exits
// 77, which CTest reports as skipped, so that a skipped case is never counted as passed.
#include <gtest/gtest.h>

#include <cstdio>

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  if (RUN_ALL_TESTS() != 0) return 1;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  if (unit.skipped_test_count() == 0) return 0;
  std::printf("%d of %d cases skipped: the batch is reported as skipped\n", unit.skipped_test_count(),
              unit.test_to_run_count());
  return 77;
}
