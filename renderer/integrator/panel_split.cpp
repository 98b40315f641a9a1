#include "renderer/integrator/panel_split.h"

#include "renderer/integrator/shared_draws.h"

namespace glossy {

Rgb traceToObject(const PathContext& context, Ray ray, CmjSampler& sampler, ObjectVertex& stop) {
  Rgb radiance(0.0);
  stop.depth = 0;
  PathState path(ray.origin);
  PathVertex v;
  for (int depth = 1; nextVertex(context, ray, sampler, depth, path, radiance, v); ++depth) {
    if (context.scene.isObject(v.mesh)) {
      stop = ObjectVertex{depth, path, radiance, v, sampler};
      break;
    }
    if (!reflect(context, depth, v, path, radiance, ray)) break;
  }
  return radiance;
}

Rgb continueFromObject(const PathContext& panel, ObjectVertex stop) {
  stop.vertex.point.brdf = &panel.scene.brdfOf(stop.vertex.mesh);
  Ray ray;
  if (reflect(panel, stop.depth, stop.vertex, stop.path, stop.radiance, ray))
    finishPath(panel, ray, stop.sampler, stop.path, stop.depth + 1, stop.radiance);
  return stop.radiance;
}

PanelSplit::PanelSplit(std::span<const PathContext> panels, bool reference)
    : panels_(panels), shared_(std::make_unique<SharedDraws>(panels.front().settings.maxDepth)),
      stops_(kWaveSize), parked_(size_t(std::max(1, panels.front().settings.maxDepth))),
      parkedPixel_(parked_.size()) {
  if (!reference)
    for (const PathContext& panel : panels) waves_.push_back(std::make_unique<WaveTracer>(panel, shared_.get()));
}

PanelSplit::~PanelSplit() = default;

void PanelSplit::trace(Ray* rays, CmjSampler* samplers, const int* pixel, int n, PanelSums& sums) {
  if (waves_.empty())
    for (int i = 0; i < n; ++i) radiance_[i] = traceToObject(panels_[0], rays[i], samplers[i], stops_[size_t(i)]);
  else
    waves_[0]->trace(rays, samplers, n, radiance_, stops_.data());
  for (int i = 0; i < n; ++i) {
    if (stops_[size_t(i)].depth > 0) {
      park(stops_[size_t(i)], pixel[i], sums);
      continue;
    }
    // Never met the object: the same path in every panel.
    for (size_t p = 0; p < panels_.size(); ++p) sums.add(p, pixel[i], radiance_[i]);
  }
}

void PanelSplit::park(const ObjectVertex& v, int pixel, PanelSums& sums) {
  ++objectPaths;
  const size_t depth = size_t(v.depth);
  parked_[depth].push_back(v);
  parkedPixel_[depth].push_back(pixel);
  if (parked_[depth].size() == size_t(kWaveSize)) resume(depth, sums);
}

void PanelSplit::resume(size_t depth, PanelSums& sums) {
  const std::vector<ObjectVertex>& vertices = parked_[depth];
  const int n = int(vertices.size());
  for (size_t p = 0; p < panels_.size(); ++p) {
    if (waves_.empty())
      for (int i = 0; i < n; ++i) resumed_[i] = continueFromObject(panels_[p], vertices[size_t(i)]);
    else
      waves_[p]->resume(vertices.data(), n, resumed_);
    for (int i = 0; i < n; ++i) sums.add(p, parkedPixel_[depth][size_t(i)], resumed_[i]);
  }
  parked_[depth].clear();
  parkedPixel_[depth].clear();
}

void PanelSplit::resumeAll(PanelSums& sums) {
  for (size_t depth = 0; depth < parked_.size(); ++depth)
    if (!parked_[depth].empty()) resume(depth, sums);
}

}  // namespace glossy
