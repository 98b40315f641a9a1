// Emissive triangles (glTF emissiveFactor) as area lights, each sampled uniformly by area. Emission is
// one-sided: from the side the triangle's winding faces, as glTF's single-sided materials imply.
#include "renderer/lights/light.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace glossy {

namespace {

class TriangleLight final : public Light {
 public:
  TriangleLight(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Rgb& radiance)
      : p0_(p0), e1_(p1 - p0), e2_(p2 - p0), radiance_(radiance) {
    const Vec3 c = glm::cross(e1_, e2_);
    area_ = 0.5 * glm::length(c);
    normal_ = area_ > 0.0 ? c / (2.0 * area_) : Vec3(0.0);
    margin_ = triangleMargin(p0, p1, p2);
  }

  double power() const override { return kPi * area_ * luminance(radiance_); }

  LightSample sample(const Receiver& at, Vec2 u) const override {
    if (!(area_ > 0.0)) return {};
    // Uniform on the triangle: p0 + √u₁(1 − u₂) e1 + √u₁ u₂ e2 (the square-root warp).
    const double r = std::sqrt(u.x);
    const Vec3 p = p0_ + r * (1.0 - u.y) * e1_ + r * u.y * e2_;
    const Vec3 d = p - at.point;
    const double distance = glm::length(d);
    if (!(distance > 0.0)) return {};
    const Vec3 wi = d / distance;
    const double cosLight = -glm::dot(wi, normal_);
    if (cosLight <= 0.0) return {};
    return {wi, radiance_, distance * distance / (cosLight * area_), false, p + normal_ * margin_};
  }

  Rgb emitted(const Hit& hit, const Receiver& from, double& pdf) const override {
    const Vec3 d = hit.position - from.point;
    const double distance2 = glm::dot(d, d);
    const double cosLight = -glm::dot(d, normal_) / std::sqrt(distance2);
    pdf = 0.0;
    if (!(cosLight > 0.0)) return Rgb(0.0);
    pdf = distance2 / (cosLight * area_);
    return radiance_;
  }

 private:
  Vec3 p0_, e1_, e2_, normal_;
  Rgb radiance_;
  double area_ = 0.0, margin_ = 0.0;
};

}  // namespace

// Every triangle of every emissive mesh, degenerate ones included (with no power, they are never chosen),
// so that each triangle a ray can hit has its light.
void emissiveTriangles(const LightSources& sources, std::vector<FoundLight>& out) {
  const SceneDescription& scene = sources.scene;
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (mesh.material < 0 || !scene.materials[size_t(mesh.material)].isEmissive()) continue;
    const Rgb radiance = scene.materials[size_t(mesh.material)].emission;
    for (size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const Vec3 p0(mesh.positions[mesh.indices[i]]), p1(mesh.positions[mesh.indices[i + 1]]),
          p2(mesh.positions[mesh.indices[i + 2]]);
      out.push_back({std::make_unique<TriangleLight>(p0, p1, p2, radiance), int(m), uint32_t(i / 3)});
    }
  }
}

}  // namespace glossy
