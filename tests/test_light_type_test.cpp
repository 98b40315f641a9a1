// A light type that only the tests have, added as the renderer's own are: one file defining its Light and
// LightFactory, and one registration line (registerLightType, light_set.h; the renderer's types are on
// light_set.cpp's line). It is a headlight: irradiance E on any surface from along its normal, a delta
// light. It finds the scene lights of type "test-headlight", which no glTF file can give (the loader
// accepts the extension's three types only), so it changes nothing for the other tests.
#include "renderer/integrator/path_tracer.h"
#include "renderer/lights/light_set.h"
#include "tests/support/render_fixtures.h"

#include <gtest/gtest.h>

namespace glossy::test {

namespace {

class Headlight final : public Light {
 public:
  explicit Headlight(const Rgb& irradiance) : irradiance_(irradiance) {}
  double power() const override { return luminance(irradiance_); }
  LightSample sample(const Receiver& at, Vec2) const override { return {at.normal, irradiance_, 1.0, true, Vec3(0.0), true}; }

 private:
  Rgb irradiance_;
};

void headlights(const LightSources& sources, std::vector<FoundLight>& out) {
  for (const SceneLight& l : sources.scene.lights)
    if (l.type == "test-headlight") out.push_back({std::make_unique<Headlight>(l.intensity)});
}

const bool kRegistered = registerLightType(headlights);

}  // namespace

// A Lambertian floor of albedo 0.5 lit by the headlight alone shows albedo/π · E everywhere.
TEST(TestLightType, ALightTypeAddedByOneFileAndOneLineRenders) {
  ASSERT_TRUE(kRegistered);
  SceneDescription d;
  d.materials = {material("floor")};
  d.meshes.push_back(quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));
  SceneLight light;
  light.type = "test-headlight";
  light.intensity = Rgb(1.0, 2.0, 4.0);
  d.lights.push_back(light);
  const EmbreeScene bvh(d);
  const RenderScene scene{&d, &bvh, {Lambertian{Rgb(0.5)}}, Lambertian{Rgb(0.5)}, nullptr};
  RenderSettings s;
  s.width = s.height = 8;
  s.spp = 4;
  s.threads = 1;
  s.progress = false;
  s.maxDepth = 2;
  RenderStats stats;
  const RgbImage image = render(scene, orthographicDown(2.0, {0, 5, 0}, {0, 0, 0}, {0, 0, -1}), s, stats);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(image.at(x, y)[c], 0.5 / kPi * light.intensity[c], 1e-6) << x << ", " << y;
}

}  // namespace glossy::test
