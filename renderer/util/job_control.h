// What a caller outside the renderer sees of a long job, and how it stops one: the work done out of the
// work expected (image tiles; total 0 while unknown, as in a sheet refined until its figures are known),
// and a request to cancel, which the job honours between tiles and passes by returning early with what it
// has. The Python module polls it from the thread that waits for the job.
#pragma once

#include <atomic>
#include <cstdint>

namespace glossy {

struct JobControl {
  std::atomic<uint64_t> done{0}, total{0};
  std::atomic<bool> cancelled{false};

  bool cancelRequested() const { return cancelled.load(std::memory_order_relaxed); }
};

}  // namespace glossy
