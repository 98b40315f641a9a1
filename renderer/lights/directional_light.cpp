// glTF KHR_lights_punctual directional lights: illuminance E arriving along one direction from infinitely
// far, so irradiance E cos θ everywhere it is not shadowed. A delta light: only its samples find it.
#include "renderer/lights/light.h"

namespace glossy {

namespace {

class DirectionalLight final : public Light {
 public:
  DirectionalLight(const Vec3& direction, const Rgb& illuminance, double sceneRadius)
      : direction_(direction), illuminance_(illuminance), sceneRadius_(sceneRadius) {}

  // What crosses the scene's bounding disk, as pbrt-v4 weighs it.
  double power() const override { return kPi * sceneRadius_ * sceneRadius_ * luminance(illuminance_); }
  LightSample sample(const Receiver&, Vec2) const override { return {-direction_, illuminance_, 1.0, true, Vec3(0.0), true}; }

 private:
  Vec3 direction_;
  Rgb illuminance_;
  double sceneRadius_;
};

}  // namespace

void directionalLights(const LightSources& sources, std::vector<FoundLight>& out) {
  for (const SceneLight& l : sources.scene.lights)
    if (l.type == "directional") out.push_back({std::make_unique<DirectionalLight>(l.direction, l.intensity, sources.sceneRadius)});
}

}  // namespace glossy
