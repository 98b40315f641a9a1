// What the throughput benchmarks share: a recorder that keeps every ray a render casts, the median of
// timed runs, and the replay of recorded rays through raw Embree (rtcIntersect1 / rtcOccluded1) alone.
// Rendering is deterministic, so a timed render casts exactly the recorded rays: the replay's rate is
// the raw Embree rate on the path tracer's own ray distribution.
#pragma once

#include "renderer/scene/embree_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace glossy::bench {

struct RecordedRay {
  RTCRay ray;
  bool shadow;
};

class Recorder : public RayRecorder {
 public:
  void record(const Ray& ray, bool shadow) override { local_.local().push_back({toRtcRay(ray), shadow}); }
  std::vector<RecordedRay> take() {
    std::vector<RecordedRay> all;
    for (auto& v : local_) all.insert(all.end(), v.begin(), v.end());
    local_.clear();
    return all;
  }

 private:
  tbb::enumerable_thread_specific<std::vector<RecordedRay>> local_;
};

template <class F>
double medianSeconds(int runs, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    f();
    t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// One pass of every recorded ray through Embree, on `threads` threads.
inline void replay(const EmbreeScene& bvh, const std::vector<RecordedRay>& rays, tbb::task_arena& arena) {
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (size_t i = r.begin(); i < r.end(); ++i) {
        if (rays[i].shadow) {
          RTCRay ray = rays[i].ray;
          rtcOccluded1(bvh.handle(), &context, &ray);
        } else {
          RTCRayHit rh;
          rh.ray = rays[i].ray;
          rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
          rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
          rtcIntersect1(bvh.handle(), &context, &rh);
        }
      }
    });
  });
}

inline double replaySeconds(const EmbreeScene& bvh, const std::vector<RecordedRay>& rays, int threads, int runs) {
  tbb::task_arena arena(threads);
  replay(bvh, rays, arena);  // warm-up: threads started, rays and BVH in cache as far as they fit
  return medianSeconds(runs, [&] { replay(bvh, rays, arena); });
}

}  // namespace glossy::bench
