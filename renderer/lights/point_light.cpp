// glTF KHR_lights_punctual point lights: intensity I in every direction from one point, so irradiance
// I cos θ / r². A delta light: only its samples find it.
#include "renderer/lights/light.h"

namespace glossy {

namespace {

class PointLight final : public Light {
 public:
  PointLight(const Vec3& position, const Rgb& intensity) : position_(position), intensity_(intensity) {}

  double power() const override { return 4.0 * kPi * luminance(intensity_); }
  LightSample sample(const Receiver& at, Vec2) const override { return towardPoint(at, position_, intensity_); }

 private:
  Vec3 position_;
  Rgb intensity_;
};

}  // namespace

void pointLights(const LightSources& sources, std::vector<FoundLight>& out) {
  for (const SceneLight& l : sources.scene.lights)
    if (l.type == "point") out.push_back({std::make_unique<PointLight>(l.position, l.intensity)});
}

}  // namespace glossy
