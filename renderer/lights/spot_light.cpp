// glTF KHR_lights_punctual spot lights: a point light within a cone about its direction, at full intensity
// inside innerConeAngle, none beyond outerConeAngle, and between them the extension's smooth falloff,
// (clamp((cos θ − cos outer) / (cos inner − cos outer), 0, 1))².
#include "renderer/lights/light.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

namespace {

class SpotLight final : public Light {
 public:
  explicit SpotLight(const SceneLight& l)
      : position_(l.position), direction_(l.direction), intensity_(l.intensity),
        cosInner_(std::cos(l.innerConeAngle)), cosOuter_(std::cos(l.outerConeAngle)) {}

  // pbrt-v4's: full intensity to the inner cone, half of it on average out to the outer one.
  double power() const override {
    return 2.0 * kPi * luminance(intensity_) * ((1.0 - cosInner_) + 0.5 * (cosInner_ - cosOuter_));
  }
  LightSample sample(const Receiver& at, Vec2) const override {
    LightSample s = towardPoint(at, position_, intensity_);
    s.radiance *= falloff(-glm::dot(s.wi, direction_));
    return s;
  }

 private:
  // The extension's, whose 1e-3 keeps a cone of equal angles (a hard edge) finite.
  double falloff(double cosTheta) const {
    const double t = std::clamp((cosTheta - cosOuter_) / std::max(1e-3, cosInner_ - cosOuter_), 0.0, 1.0);
    return t * t;
  }

  Vec3 position_, direction_;
  Rgb intensity_;
  double cosInner_, cosOuter_;
};

}  // namespace

void spotLights(const LightSources& sources, std::vector<FoundLight>& out) {
  for (const SceneLight& l : sources.scene.lights)
    if (l.type == "spot") out.push_back({std::make_unique<SpotLight>(l)});
}

}  // namespace glossy
