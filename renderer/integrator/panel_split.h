// The panel split of a sheet: its panels differ only in the BRDF of the object (RenderScene::objectMeshes),
// so a path is traced once up to its first vertex on the object, with that vertex's draws, light samples
// and shadow rays, none of which depends on the object's BRDF; from there each panel continues it with its
// own. A path that never meets the object is the same in every panel.
#pragma once

#include "renderer/integrator/path_vertex.h"
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
  uint32_t mesh = 0;
  PathState path;
  Rgb radiance{0.0};       // gathered before the vertex
  ShadingPoint point;      // its brdf is the first panel's; each panel sets its own
  VertexDraws draws;
  VertexLight light;
  CmjSampler sampler;      // past the vertex's draws
};

// A panel's paths, a wave at a time, on one thread.
class PanelPaths {
 public:
  PanelPaths(const PathContext& panel, SharedDraws* shared) : panel_(panel), shared_(shared), paths_(panel) {}

  // radiance[i] of the camera rays[i], i < n. With stops, a path that reaches the object stops there,
  // stops[i] its vertex (depth 0 for the others), radiance[i] what it gathered before.
  void trace(Ray* rays, CmjSampler* samplers, int n, Rgb* radiance, ObjectVertex* stops) {
    for (int first = 0; first < n; first += kWaveSize) {
      const Lanes lanes = Lanes::first(std::min(kWaveSize, n - first));
      ObjectVertex* stop = stops ? stops + first : nullptr;
      for (const int i : lanes) {
        paths_.path[i] = PathState(rays[first + i].origin);
        radiance[first + i] = Rgb(0.0);
        if (stop) stop[i].depth = 0;
      }
      paths_.walk(1, lanes, rays + first, samplers + first, radiance + first, nullptr, [&](int depth, const Lanes& at) {
        if (!stop) return at;
        Lanes on;
        for (const int i : at)
          if (panel_.scene.isObject(paths_.hit[i].mesh))
            stop[i] = {depth, paths_.hit[i].mesh, paths_.path[i], radiance[first + i], paths_.point[i], paths_.draws[i],
                       paths_.light[i], samplers[first + i]};
          else
            on.add(i);
        return on;
      });
    }
  }

  // radiance[i] of the stopped paths vertices[i], i < n, all of one depth, finished in this panel: its
  // context differs from the one that traced them only in the object's BRDF. The paths of the panels' waves
  // share what they draw alike (shared_draws.h).
  void resume(const ObjectVertex* vertices, int n, Rgb* radiance) {
    for (int first = 0; first < n; first += kWaveSize) {
      const Lanes lanes = Lanes::first(std::min(kWaveSize, n - first));
      for (const int i : lanes) {
        const ObjectVertex& v = vertices[first + i];
        paths_.path[i] = v.path;
        radiance[first + i] = v.radiance;
        paths_.point[i] = v.point;
        paths_.point[i].brdf = &panel_.scene.brdfOf(v.mesh);
        paths_.point[i].lightSamples = panel_.lightSamplesAt(v.mesh, v.depth);
        paths_.point[i].bsdfSamples = panel_.bsdfSamplesAt(v.mesh, v.depth);
        paths_.draws[i] = v.draws;
        paths_.light[i] = v.light;
        samplers_[i] = v.sampler;
      }
      const int depth = vertices[first].depth;
      paths_.walk(depth + 1, paths_.reflect(depth, lanes, rays_, radiance + first), rays_, samplers_, radiance + first, shared_,
                  [](int, const Lanes& at) { return at; });
    }
  }

 private:
  const PathContext& panel_;
  SharedDraws* shared_;
  Paths paths_;
  Ray rays_[kWaveSize];
  CmjSampler samplers_[kWaveSize];
};

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

// A thread's tracer of the panels' camera paths, a wave at a time. With more than one panel, a path that reaches the object is parked there, by
// depth, until its depth has a wave's worth (a wave advances its lanes one depth at a time); then every
// panel continues them, sharing what they draw alike (shared_draws.h). One panel's paths run to their end,
// with none of this.
class PanelTracer {
 public:
  explicit PanelTracer(std::span<const PathContext> panels)
      : panels_(panels), shared_(panels[0].settings.maxDepth), parked_(size_t(std::max(1, panels[0].settings.maxDepth))) {
    for (const PathContext& panel : panels)
      waves_.push_back(std::make_unique<PanelPaths>(panel, panels.size() > 1 ? &shared_ : nullptr));
  }

  // The camera rays of the tile's samples of pixel[i], i < n, added to sums where their paths end.
  void trace(Ray* rays, CmjSampler* samplers, const int* pixel, int n, PanelSums& sums) {
    ObjectVertex* stops = panels_.size() > 1 ? stops_ : nullptr;
    waves_[0]->trace(rays, samplers, n, radiance_, stops);
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
      waves_[p]->resume(parked.vertices.data(), n, resumed_);
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
  std::vector<std::unique_ptr<PanelPaths>> waves_;  // per panel
  std::vector<Parked> parked_;                      // [depth]
  ObjectVertex stops_[kWaveSize];
  Rgb radiance_[kWaveSize], resumed_[kWaveSize];    // per lane
};

}  // namespace glossy
