// The passes of a sheet's render: how many samples each replicate takes in each, for a fixed spp, a time
// budget or a target error (renderSheet, sheet.cpp).
#pragma once

#include "renderer/sheet/sheet.h"

#include <algorithm>
#include <cmath>

namespace glossy {

// From this many spp the intervals held whatever the noise's share (the coverage sweep's lowest count).
constexpr int kTrustedSpp = 64;

// The replicates' sample counts, pass after pass: fixed (one pass), equal time (1, 2, 4, … per replicate
// until the next would overrun the budget) or a target error (as many as the intervals' widths say).
class PassPlan {
 public:
  PassPlan(const SheetSettings& s, int panelsRendered)
      : s_(s), replicates_(s.secondsPerPanel > 0.0 || s.targetError > 0.0 ? kReplicates : std::clamp(s.spp, 1, kReplicates)),
        budget_(s.secondsPerPanel * panelsRendered) {}
  int replicates() const { return replicates_; }

  // Samples per replicate of the next pass, given those done and the figures so far (their widest interval,
  // and whether noise dominates them); 0: stop.
  int next(int done, double seconds, double lastPassSeconds, double widest, bool noisy) {
    const int cap = (s_.spp + replicates_ - 1) / replicates_;
    if (s_.targetError > 0.0) {
      if (done == 0) return std::min(cap, 4);
      // No interval to refine (no measured panel, or it is black over the object): nothing to aim at.
      if (!std::isfinite(widest) || (widest <= s_.targetError && !noisy) || done >= cap) return 0;
      // Half-widths shrink as 1/√samples: aim a little past the estimate, at most quadrupling; while noise
      // dominates, a narrow interval is not yet to be trusted: double, but no further than the spp from
      // which it is.
      const double ratio = widest / s_.targetError;
      double wanted = std::ceil(1.1 * done * ratio * ratio);
      if (noisy) wanted = std::max(wanted, std::min(std::ceil(2.2 * done), std::ceil(double(kTrustedSpp) / replicates_)));
      wanted = std::min(4.0 * done, wanted);
      int n = std::clamp(int(wanted) - done, 1, cap - done);
      if (budget_ > 0.0) {
        const double perSample = lastPassSeconds / std::max(1, lastPass_);
        n = std::min(n, int((budget_ - seconds) / std::max(perSample, 1e-9)));
      }
      lastPass_ = n;
      return std::max(n, 0);
    }
    if (budget_ > 0.0) {
      if (done == 0) return lastPass_ = std::min(1, cap);
      if (done >= cap || seconds + 2.0 * lastPassSeconds > budget_) return 0;
      return lastPass_ = std::min(done, cap - done);  // doubling, up to the --spp cap
    }
    return done == 0 ? cap : 0;
  }

 private:
  const SheetSettings& s_;
  int replicates_;
  double budget_;
  int lastPass_ = 0;  // samples per replicate of the last pass
};

}  // namespace glossy
