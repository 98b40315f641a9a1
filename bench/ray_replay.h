// What the throughput benchmarks share: a recorder that keeps every query a render makes, and the replay of the recorded rays through raw Embree alone — either one ray at a time
// (rtcIntersect1 / rtcOccluded1: Embree's basic rate on these rays) or grouped exactly as the path tracer
// grouped them (rtcIntersect8 / rtcOccluded8 for its packets: the raw cost of its own calls). Rendering
// is deterministic, so a timed render casts exactly the recorded rays.
#pragma once

#include "bench/timing.h"
#include "renderer/scene/embree_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <vector>

namespace glossy::bench {

// One Embree call of the render: a single ray (lanes = 1, not a packet) or a packet of kPacketSize lanes.
struct RecordedQuery {
  RTCRay rays[kPacketSize];
  bool valid[kPacketSize] = {};
  bool packet = false;
  bool shadow = false;
};

struct RecordedRays {
  std::vector<RecordedQuery> queries;
  size_t rays = 0;     // valid lanes over all queries
  size_t packets = 0;  // queries that were packets
};

enum class Replay { OneRayAtATime, AsRecorded };

class Recorder : public RayRecorder {
 public:
  void record(const Ray& ray, bool shadow) override {
    RecordedQuery q;
    q.rays[0] = toRtcRay(ray);
    q.valid[0] = true;
    q.shadow = shadow;
    local_.local().push_back(q);
  }
  void recordPacket(const Ray* rays, const bool* valid, bool shadow) override {
    RecordedQuery q;
    q.packet = true;
    q.shadow = shadow;
    bool any = false;
    for (int i = 0; i < kPacketSize; ++i)
      if ((q.valid[i] = valid[i])) {
        q.rays[i] = toRtcRay(rays[i]);
        any = true;
      }
    if (any) local_.local().push_back(q);
  }
  RecordedRays take() {
    RecordedRays all;
    for (auto& v : local_) all.queries.insert(all.queries.end(), v.begin(), v.end());
    local_.clear();
    for (const RecordedQuery& q : all.queries) {
      all.rays += size_t(std::count(q.valid, q.valid + kPacketSize, true));
      all.packets += q.packet ? 1 : 0;
    }
    return all;
  }

 private:
  tbb::enumerable_thread_specific<std::vector<RecordedQuery>> local_;
};

namespace detail {

inline void traceOne(RTCScene scene, RTCIntersectContext& context, const RTCRay& ray, bool shadow) {
  if (shadow) {
    RTCRay r = ray;
    rtcOccluded1(scene, &context, &r);
  } else {
    RTCRayHit rh;
    rh.ray = ray;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
  }
}

inline void tracePacket(RTCScene scene, RTCIntersectContext& context, const RecordedQuery& q) {
  alignas(32) int mask[kPacketSize];
  alignas(32) RTCRayHit8 packet;
  for (int i = 0; i < kPacketSize; ++i) setPacketHitLane(packet, mask, i, q.valid[i] ? &q.rays[i] : nullptr);
  if (q.shadow)
    rtcOccluded8(mask, scene, &context, &packet.ray);
  else
    rtcIntersect8(mask, scene, &context, &packet);
}

}  // namespace detail

// One pass of every recorded query through Embree, on the arena's threads.
inline void replay(const EmbreeScene& bvh, const RecordedRays& rays, Replay mode, tbb::task_arena& arena) {
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.queries.size(), 1024), [&](const tbb::blocked_range<size_t>& r) {
      RTCIntersectContext context;
      rtcInitIntersectContext(&context);
      for (size_t k = r.begin(); k < r.end(); ++k) {
        const RecordedQuery& q = rays.queries[k];
        if (q.packet && mode == Replay::AsRecorded) {
          detail::tracePacket(bvh.handle(), context, q);
        } else {
          for (int i = 0; i < kPacketSize; ++i)
            if (q.valid[i]) detail::traceOne(bvh.handle(), context, q.rays[i], q.shadow);
        }
      }
    });
  });
}

inline double replaySeconds(const EmbreeScene& bvh, const RecordedRays& rays, Replay mode, int threads, int runs) {
  tbb::task_arena arena(threads);
  replay(bvh, rays, mode, arena);  // warm-up: threads started, rays and BVH in cache as far as they fit
  return medianSeconds(runs, [&] { replay(bvh, rays, mode, arena); });
}

}  // namespace glossy::bench
