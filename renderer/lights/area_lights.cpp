#include "renderer/lights/area_lights.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

AreaLights::AreaLights(const SceneDescription& scene) {
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.material < 0 || !scene.materials[size_t(mesh.material)].isEmissive()) continue;
    const Rgb radiance = scene.materials[size_t(mesh.material)].emission;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const Vec3 p0(mesh.positions[mesh.indices[i]]), p1(mesh.positions[mesh.indices[i + 1]]),
          p2(mesh.positions[mesh.indices[i + 2]]);
      const Vec3 c = glm::cross(p1 - p0, p2 - p0);
      const double area = 0.5 * glm::length(c);
      if (!(area > 0.0)) continue;
      triangles_.push_back({p0, p1 - p0, p2 - p0, c / (2.0 * area), radiance});
      totalArea_ += area;
      cdf_.push_back(totalArea_);
    }
  }
}

AreaLights::Sample AreaLights::sample(double uTriangle, Vec2 u) const {
  if (empty()) return {};
  const double target = uTriangle * totalArea_;
  const size_t i = std::min<size_t>(size_t(std::upper_bound(cdf_.begin(), cdf_.end(), target) - cdf_.begin()),
                                    triangles_.size() - 1);
  const Triangle& tri = triangles_[i];
  // Uniform point on the triangle: p0 + √u₁(1 − u₂) e1 + √u₁ u₂ e2 (the square-root warp).
  const double r = std::sqrt(u.x);
  const double b1 = r * (1.0 - u.y), b2 = r * u.y;
  return {tri.p0 + b1 * tri.e1 + b2 * tri.e2, tri.normal, tri.radiance, 1.0 / totalArea_};
}

}  // namespace glossy
