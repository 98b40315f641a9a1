// What the path tracer asks of a light, whatever its kind: a sample toward a shading point, the density
// of that sample, and the radiance a ray that reaches the light brings. Distant lights (the environment)
// are reached by rays that leave the scene; surface lights (emissive triangles) by rays that hit them;
// delta lights (point, spot, directional) by no ray: only their samples find them, so MIS gives those
// samples weight 1.
//
// Adding a light type: one file that defines a Light and a LightFactory for it, and its factory's name in
// the registration line of light_set.cpp (docs/rendering.md).
#pragma once

#include "materials/core/types.h"
#include "renderer/scene/embree_scene.h"

#include <cmath>
#include <memory>
#include <vector>

namespace glossy {

class Environment;

// Where a light is seen from: a point and the normal of the surface there (the shading normal, on the
// side the light must arrive from). Below the normal's horizon the surface takes no light, so a light may
// shape its samples by it (the environment does). The zero normal: no surface, e.g. a camera.
struct Receiver {
  Vec3 point{0.0};
  Vec3 normal{0.0};
};

// A light sample seen from a point.
struct LightSample {
  Vec3 wi{0.0};        // unit, from the point toward the light
  Rgb radiance{0.0};   // arriving at the point along −wi if nothing blocks it
  double pdf = 0.0;    // solid angle at the point; 0: no sample. A delta light's: its choice alone, 1
  // The light lies at infinity, and so does the shadow ray's end (the environment's, a directional light's);
  // not Light::distant(), which says whether rays that leave the scene find the light.
  bool atInfinity = true;
  Vec3 target{0.0};    // a surface light's point, moved off its surface toward the point by its margin
  bool delta = false;  // from a light no BSDF sample can hit: radiance is what arrives, not a density
};

// The sample of a light at one point (point and spot lights) with intensity I seen from `at`: I / r².
inline LightSample towardPoint(const Receiver& at, const Vec3& position, const Rgb& intensity) {
  const Vec3 d = position - at.point;
  const double distance2 = d.x * d.x + d.y * d.y + d.z * d.z;
  if (!(distance2 > 0.0)) return {};
  return {d / std::sqrt(distance2), intensity / distance2, 1.0, false, position, true};
}

class Light {
 public:
  virtual ~Light() = default;

  // Emitted power (luminance), what the light chooser weighs lights by.
  virtual double power() const = 0;
  virtual bool distant() const { return false; }

  virtual LightSample sample(const Receiver& at, Vec2 u) const = 0;
  // out[lanes[k]] = sample(at[lanes[k]], u[lanes[k]]) for k < n: a kind whose samples read memory at
  // random overrides it to issue the lanes' reads together.
  virtual void sample(const Receiver* at, const Vec2* u, const int* lanes, int n, LightSample* out) const {
    for (int k = 0; k < n; ++k) out[lanes[k]] = sample(at[lanes[k]], u[lanes[k]]);
  }

  // Distant lights: the radiance from direction dir, and the density sample(from, ·) draws dir with.
  virtual Rgb arriving(const Vec3& /*dir*/, const Receiver& /*from*/, double& pdf) const {
    pdf = 0.0;
    return Rgb(0.0);
  }
  virtual void arriving(const Vec3* dirs, const Receiver* from, const int* lanes, int n, Rgb* radiance, double* pdf) const {
    for (int k = 0; k < n; ++k) radiance[lanes[k]] = arriving(dirs[lanes[k]], from[lanes[k]], pdf[lanes[k]]);
  }

  // Surface lights: the radiance leaving the hit point toward the ray's origin `from`, and the density
  // (solid angle at `from`) with which sample(from, ·) would have drawn it.
  virtual Rgb emitted(const Hit& /*hit*/, const Receiver& /*from*/, double& pdf) const {
    pdf = 0.0;
    return Rgb(0.0);
  }
};

// What a light type may find its lights in.
struct LightSources {
  const SceneDescription& scene;
  const Environment* environment;  // may be null
  double sceneRadius;              // of a sphere around all geometry
};

// The lights a type finds in a scene. A surface light names the triangle it covers, so that a ray that
// hits that triangle finds it.
struct FoundLight {
  std::unique_ptr<Light> light;
  int mesh = -1;  // surface lights: the triangle (mesh, triangle) it covers
  uint32_t triangle = 0;
};
using LightFactory = void(const LightSources&, std::vector<FoundLight>&);

}  // namespace glossy
