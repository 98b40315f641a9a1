// The reference path tracer (path_reference.cpp), batched: the paths of up to kWaveSize samples advance
// together, one vertex at a time, each of its steps (path_vertex.h) taken for all lanes before the next.
// With stops, it is the panel split's (panel_split.h) traceToObject; resume is its continueFromObject.
#pragma once

#include "renderer/integrator/path_vertex.h"

namespace glossy {

class SharedDraws;
struct ObjectVertex;  // panel_split.h

// Li for up to kWaveSize camera rays at once: radiance[i] for the lanes i < n. With stops,
// traceToObject instead: a lane whose path reaches the object stops there, stops[i] its vertex (depth 0 for
// the others). continueFromObject for n vertices of one depth: resume. Its lanes' state lives in the
// tracer, made once per thread and reused, as it is too large to clear per wave. The panels' tracers of a
// thread may share a SharedDraws (shared_draws.h), which resume then uses.
class WaveTracer {
 public:
  explicit WaveTracer(const PathContext& context, SharedDraws* shared = nullptr) : context_(context), shared_(shared) {}
  void trace(Ray* rays, CmjSampler* samplers, int n, Rgb* radiance, ObjectVertex* stops = nullptr);
  void resume(const ObjectVertex* vertices, int n, Rgb* radiance);

 private:
  void walk(int depth, Ray* rays, CmjSampler* samplers, bool* alive, Rgb* radiance, ObjectVertex* stops);
  void reflectAll(int depth, const Lanes& lanes, Ray* rays, bool* alive, Rgb* radiance);
  void sampleBrdf(const Brdf& brdf, const Lanes& group);

  const PathContext& context_;
  SharedDraws* shared_;
  PathState path_[kWaveSize];
  Hit hit_[kWaveSize];
  bool found_[kWaveSize];
  Vec3 direction_[kWaveSize];  // of the rays that left the scene
  Rgb arriving_[kWaveSize];
  double pdf_[kWaveSize];
  ShadingPoint point_[kWaveSize];
  VertexDraws draws_[kWaveSize];
  Receiver from_[kWaveSize];  // the escaped rays' vertices
  VertexLight light_[kWaveSize];
  DirectLight<kWaveSize> direct_;
  Rgb throughput_[kWaveSize];
  BrdfSample bsdfSample_[kWaveSize];
  Ray resumeRays_[kWaveSize];
  CmjSampler resumeSamplers_[kWaveSize];
};

}  // namespace glossy
