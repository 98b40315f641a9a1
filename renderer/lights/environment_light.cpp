// The environment (environment.h) as a distant light: its samples depend on the normal they are seen
// with, not on the point, and rays that leave the scene see it.
#include "renderer/lights/environment.h"
#include "renderer/lights/light.h"

namespace glossy {

namespace {

class EnvironmentLight final : public Light {
 public:
  EnvironmentLight(const Environment& environment, double sceneRadius)
      : environment_(environment), sceneRadius_(sceneRadius) {}

  // What crosses the scene's bounding disk from every direction.
  double power() const override {
    return kPi * sceneRadius_ * sceneRadius_ * 4.0 * kPi * environment_.meanLuminance();
  }
  bool distant() const override { return true; }

  LightSample sample(const Receiver& at, Vec2 u) const override { return lightSample(environment_.sample(at.normal, u)); }
  // The map's reads for all lanes at once (environment.h): the same values as one at a time. The
  // environment's batches take the lanes as a mask over the first kMaxBatch.
  void sample(const Receiver* at, const Vec2* u, const int* lanes, int n, LightSample* out) const override {
    bool want[Environment::kMaxBatch] = {};
    if (!mask(lanes, n, want)) return Light::sample(at, u, lanes, n, out);
    Vec3 normals[Environment::kMaxBatch] = {};  // zeroed: only the wanted lanes are read, which GCC cannot see
    for (int k = 0; k < n; ++k) normals[lanes[k]] = at[lanes[k]].normal;
    Environment::Sample samples[Environment::kMaxBatch];
    environment_.sample(want, normals, u, samples, lanes[n - 1] + 1);
    for (int k = 0; k < n; ++k) out[lanes[k]] = lightSample(samples[lanes[k]]);
  }

  Rgb arriving(const Vec3& dir, const Receiver& from, double& pdf) const override {
    return environment_.radianceAndPdf(from.normal, dir, pdf);
  }
  void arriving(const Vec3* dirs, const Receiver* from, const int* lanes, int n, Rgb* radiance, double* pdf) const override {
    bool want[Environment::kMaxBatch] = {};
    if (!mask(lanes, n, want)) return Light::arriving(dirs, from, lanes, n, radiance, pdf);
    Vec3 normals[Environment::kMaxBatch] = {};  // zeroed: only the wanted lanes are read, which GCC cannot see
    for (int k = 0; k < n; ++k) normals[lanes[k]] = from[lanes[k]].normal;
    environment_.radianceAndPdf(want, normals, dirs, radiance, pdf, lanes[n - 1] + 1);
  }

 private:
  static LightSample lightSample(const Environment::Sample& s) { return {s.dir, s.radiance, s.pdf, true, Vec3(0.0)}; }
  // want[lanes[k]] for increasing lanes; false if there are none or they reach past the mask.
  static bool mask(const int* lanes, int n, bool* want) {
    if (n == 0 || lanes[n - 1] >= Environment::kMaxBatch) return false;
    for (int k = 0; k < n; ++k) want[lanes[k]] = true;
    return true;
  }

  const Environment& environment_;
  double sceneRadius_;
};

}  // namespace

void environmentLight(const LightSources& sources, std::vector<FoundLight>& out) {
  if (sources.environment)
    out.push_back({std::make_unique<EnvironmentLight>(*sources.environment, sources.sceneRadius), -1, 0});
}

}  // namespace glossy
