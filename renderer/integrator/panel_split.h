// The panel split of a sheet: its panels differ only in the BRDF of the object (RenderScene::objectMeshes),
// so a path is traced once up to its first vertex on the object, with that vertex's draws, light samples
// and shadow rays, none of which depends on the object's BRDF; from there each panel continues it with its
// own. A path that never meets the object is the same in every panel.
#pragma once

#include "renderer/integrator/path_vertex.h"

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
Rgb traceToObject(const PathContext& context, Ray ray, CmjSampler& sampler, ObjectVertex& stop);
Rgb continueFromObject(const PathContext& panel, ObjectVertex stop);

// A tile's sums of its samples' radiance, per panel and pixel; a non-finite sample is dropped, and counted.
struct PanelSums {
  size_t pixels = 0;
  std::vector<Rgb> sum;  // [panel][pixel]
  uint64_t dropped = 0;
  void add(size_t panel, int pixel, const Rgb& r) {
    if (std::isfinite(r.r) && std::isfinite(r.g) && std::isfinite(r.b))
      sum[panel * pixels + size_t(pixel)] += r;
    else
      ++dropped;
  }
};

class WaveTracer;
class SharedDraws;

// A thread's tracer of the panels together, a wave of camera paths at a time (or each by the reference,
// RenderSettings::reference). A path that reaches the object is parked there, by depth, until its depth has
// a wave's worth (a wave advances its lanes one depth at a time); then every panel continues them.
class PanelSplit {
 public:
  PanelSplit(std::span<const PathContext> panels, bool reference);
  ~PanelSplit();
  // The camera rays of the tile's samples of pixel[i], i < n, added to sums where their paths end.
  void trace(Ray* rays, CmjSampler* samplers, const int* pixel, int n, PanelSums& sums);
  // Continues every parked path: before the tile ends, as their samplers point at its pixels.
  void resumeAll(PanelSums& sums);
  uint64_t objectPaths = 0;  // paths that reached the object

 private:
  void park(const ObjectVertex& v, int pixel, PanelSums& sums);
  void resume(size_t depth, PanelSums& sums);

  std::span<const PathContext> panels_;
  std::unique_ptr<SharedDraws> shared_;
  std::vector<std::unique_ptr<WaveTracer>> waves_;  // per panel; none for the reference
  std::vector<ObjectVertex> stops_;                 // per lane
  std::vector<std::vector<ObjectVertex>> parked_;   // [depth]
  std::vector<std::vector<int>> parkedPixel_;       // [depth]
  Rgb radiance_[kWaveSize], resumed_[kWaveSize];    // per lane
};

}  // namespace glossy
