#include "renderer/integrator/panel_split.h"

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

}  // namespace glossy
