// The wave against the reference path tracer in every configuration the wave treats differently
// (tracer_comparison.h), with the samples for each 16 × 16 block's test to catch a 1 % bias with 99 %
// probability (TracerCase::sppForOnePercent): 2 to 112 times the default suite's samples
// (Integrator.TheWaveMatchesTheReferencePathTracerBlockByBlock).
#include "tests/support/tracer_comparison.h"

#include <gtest/gtest.h>

namespace glossy::test {

TEST(TracerSweep, TheWaveMatchesTheReferenceToOnePercentPerBlock) {
  for (const TracerCase& c : tracerCases()) {
    const BlockCheck check = compareTracers(c, c.sppForOnePercent, 16);
    EXPECT_LT(check.worstZ, 4.5) << c.name;
    EXPECT_GT(check.lit, 0) << c.name;
    EXPECT_LE(check.worstDetectable, 0.01) << c.name;
  }
}

}  // namespace glossy::test
