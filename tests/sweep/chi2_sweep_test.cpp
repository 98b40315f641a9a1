// The χ² sampler test over every fit of the library (about 400) at the four view angles: the long sweep,
// run with `ctest -L sweep` (scripts/test leaves it out; it takes about ten minutes on 2 cores). The default
// suite's family (tests/sampling_chi2_test.cpp) covers the supplement and the most extreme fits.
#include "tests/support/sampling_cases.h"

#include <gtest/gtest.h>

namespace glossy::test {

namespace {

const std::vector<SamplingCase>& sweep() {
  static const std::vector<SamplingCase> cases = [] {
    std::vector<SamplingCase> all;
    for (const LibraryFit& f : libraryFits())
      for (const SamplingCase& c : atViewAngles(f)) all.push_back(c);
    // SGD's three cases, not its 100 fits: its tabulated density is slow to integrate (sampling_cases.cpp).
    for (const LibraryFit& f : sgdChi2Fits())
      for (const SamplingCase& c : atViewAngles(f)) all.push_back(c);
    return all;
  }();
  return cases;
}

class Chi2Sweep : public ::testing::TestWithParam<SamplingCase> {};

}  // namespace

TEST_P(Chi2Sweep, SampleDrawsFromExactlyThePdf) {
  const SamplingCase& c = GetParam();
  const SamplingCheck check = checkSampler(c, 1000000, c.seed() ^ 0x5eedu, sidakAlpha(0.01, int(sweep().size())));
  EXPECT_TRUE(check.chi2.passed) << c.label() << ": " << check.chi2.message;
  EXPECT_EQ(check.weightMismatches, 0) << c.label();
}

INSTANTIATE_TEST_SUITE_P(Library, Chi2Sweep, ::testing::ValuesIn(sweep()),
                         [](const auto& info) { return info.param.testName(); });

}  // namespace glossy::test
