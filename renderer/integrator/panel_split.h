// The panel split of a sheet: its panels differ only in the BRDF of the object (RenderScene::objectMeshes),
// so a path is traced once up to its first vertex on the object, with that vertex's draws, light samples
// and shadow rays, none of which depends on the object's BRDF; from there each panel continues it with its
// own. A path that never meets the object is the same in every panel.
#pragma once

#include "renderer/integrator/shared_draws.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <vector>

namespace glossy {

// A path at its first vertex on the object, before the vertex's BRDF acts: all that the panels share.
struct ObjectVertex {
  int depth = 0;           // 0: the path never reached the object
  PathState path;
  Rgb radiance{0.0};       // gathered before the vertex
  PathVertex vertex;       // its point's brdf is the first panel's; each panel sets its own
  CmjSampler sampler;      // past the vertex's draws
};

// Li, but a path that reaches the object stops there, stop its vertex (stop.depth is 0 when it did not
// stop): the radiance so far. continueFromObject then finishes it for a panel, whose context differs only
// in the object's BRDF. The two make exactly Li's radiance.
inline Rgb traceToObject(const PathContext& context, Ray ray, CmjSampler& sampler, ObjectVertex& stop) {
  Rgb radiance(0.0);
  stop.depth = 0;
  PathState path(ray.origin);
  PathVertex v;
  for (int depth = 1; nextVertex(context, ray, sampler, depth, path, radiance, v); ++depth) {
    if (context.scene.isObject(v.mesh)) return (stop = ObjectVertex{depth, path, radiance, v, sampler}).radiance;
    if (!reflect(context, depth, v, path, radiance, ray)) break;
  }
  return radiance;
}

inline Rgb continueFromObject(const PathContext& panel, ObjectVertex stop) {
  stop.vertex.point.brdf = &panel.scene.brdfOf(stop.vertex.mesh);
  stop.vertex.point.lightSamples = panel.lightSamplesAt(stop.vertex.mesh, stop.depth);
  Ray ray;
  if (reflect(panel, stop.depth, stop.vertex, stop.path, stop.radiance, ray))
    finishPath(panel, ray, stop.sampler, stop.path, stop.depth + 1, stop.radiance);
  return stop.radiance;
}

// A tile's sums of its samples' radiance, per panel and pixel; a non-finite sample is dropped, and counted.
struct PanelSums {
  size_t pixels = 0;
  std::vector<Rgb> sum;  // [panel][pixel]
  uint64_t dropped = 0;
  void add(size_t panel, int pixel, const Rgb& r) {
    if (std::isfinite(r.r) && std::isfinite(r.g) && std::isfinite(r.b)) sum[panel * pixels + size_t(pixel)] += r;
    else ++dropped;
  }
};

// A thread's tracer of the panels' camera paths, a wave at a time (or each by the reference,
// RenderSettings::reference). With more than one panel, a path that reaches the object is parked there, by
// depth, until its depth has a wave's worth (a wave advances its lanes one depth at a time); then every
// panel continues them, sharing what they draw alike (shared_draws.h). One panel's paths run to their end,
// with none of this.
class PanelTracer {
 public:
  PanelTracer(std::span<const PathContext> panels, bool reference)
      : panels_(panels), shared_(panels[0].settings.maxDepth), parked_(size_t(std::max(1, panels[0].settings.maxDepth))) {
    for (size_t p = 0; p < panels.size() && !reference; ++p)
      waves_.push_back(std::make_unique<WaveTracer>(panels[p], panels.size() > 1 ? &shared_ : nullptr));
  }

  // The camera rays of the tile's samples of pixel[i], i < n, added to sums where their paths end.
  void trace(Ray* rays, CmjSampler* samplers, const int* pixel, int n, PanelSums& sums) {
    ObjectVertex* stops = panels_.size() > 1 ? stops_ : nullptr;
    if (!waves_.empty())
      waves_[0]->trace(rays, samplers, n, radiance_, stops);
    else
      for (int i = 0; i < n; ++i)
        radiance_[i] = stops ? traceToObject(panels_[0], rays[i], samplers[i], stops[i]) : Li(panels_[0], rays[i], samplers[i]);
    for (int i = 0; i < n; ++i)
      if (stops && stops[i].depth > 0)
        park(stops[i], pixel[i], sums);
      else  // never met the object: the same path in every panel
        for (size_t p = 0; p < panels_.size(); ++p) sums.add(p, pixel[i], radiance_[i]);
  }

  // Continues every parked path: before the tile ends, as their samplers point at its pixels.
  void resumeAll(PanelSums& sums) {
    for (size_t depth = 0; depth < parked_.size(); ++depth) resume(depth, sums);
  }

  uint64_t objectPaths = 0;  // paths that reached the object

 private:
  void park(const ObjectVertex& v, int pixel, PanelSums& sums) {
    ++objectPaths;
    Parked& parked = parked_[size_t(v.depth)];
    parked.vertices.push_back(v);
    parked.pixels.push_back(pixel);
    if (parked.vertices.size() == size_t(kWaveSize)) resume(size_t(v.depth), sums);
  }

  void resume(size_t depth, PanelSums& sums) {
    Parked& parked = parked_[depth];
    const int n = int(parked.vertices.size());
    for (size_t p = 0; p < panels_.size(); ++p) {
      if (!waves_.empty())
        waves_[p]->resume(parked.vertices.data(), n, resumed_);
      else
        for (int i = 0; i < n; ++i) resumed_[i] = continueFromObject(panels_[p], parked.vertices[size_t(i)]);
      for (int i = 0; i < n; ++i) sums.add(p, parked.pixels[size_t(i)], resumed_[i]);
    }
    parked.vertices.clear();
    parked.pixels.clear();
  }

  struct Parked {
    std::vector<ObjectVertex> vertices;
    std::vector<int> pixels;  // the tile's, of their samples
  };
  std::span<const PathContext> panels_;
  SharedDraws shared_;
  std::vector<std::unique_ptr<WaveTracer>> waves_;  // per panel; none for the reference
  std::vector<Parked> parked_;                      // [depth]
  ObjectVertex stops_[kWaveSize];
  Rgb radiance_[kWaveSize], resumed_[kWaveSize];    // per lane
};

}  // namespace glossy
