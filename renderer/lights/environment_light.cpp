// The environment (environment.h) as a distant light: its samples do not depend on the point they are
// seen from, and rays that leave the scene see it.
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

  LightSample sample(const Vec3& /*point*/, Vec2 u) const override { return lightSample(environment_.sample(u)); }
  // The map's reads for all lanes at once (environment.h): the same values as one at a time.
  void sample(const Vec3* /*points*/, const Vec2* u, const int* lanes, int n, LightSample* out) const override {
    Vec2 packed[Environment::kMaxBatch];
    Environment::Sample samples[Environment::kMaxBatch];
    bool want[Environment::kMaxBatch];
    for (int first = 0; first < n; first += Environment::kMaxBatch) {
      const int count = std::min(Environment::kMaxBatch, n - first);
      for (int k = 0; k < count; ++k) {
        packed[k] = u[lanes[first + k]];
        want[k] = true;
      }
      environment_.sample(want, packed, samples, count);
      for (int k = 0; k < count; ++k) out[lanes[first + k]] = lightSample(samples[k]);
    }
  }

  Rgb arriving(const Vec3& dir, double& pdf) const override { return environment_.radianceAndPdf(dir, pdf); }
  void arriving(const Vec3* dirs, const int* lanes, int n, Rgb* radiance, double* pdf) const override {
    Vec3 packed[Environment::kMaxBatch];
    Rgb r[Environment::kMaxBatch];
    double p[Environment::kMaxBatch];
    bool want[Environment::kMaxBatch];
    for (int first = 0; first < n; first += Environment::kMaxBatch) {
      const int count = std::min(Environment::kMaxBatch, n - first);
      for (int k = 0; k < count; ++k) {
        packed[k] = dirs[lanes[first + k]];
        want[k] = true;
      }
      environment_.radianceAndPdf(want, packed, r, p, count);
      for (int k = 0; k < count; ++k) {
        radiance[lanes[first + k]] = r[k];
        pdf[lanes[first + k]] = p[k];
      }
    }
  }

 private:
  static LightSample lightSample(const Environment::Sample& s) { return {s.dir, s.radiance, s.pdf, true, Vec3(0.0)}; }

  const Environment& environment_;
  double sceneRadius_;
};

}  // namespace

void environmentLight(const LightSources& sources, std::vector<FoundLight>& out) {
  if (sources.environment)
    out.push_back({std::make_unique<EnvironmentLight>(*sources.environment, sources.sceneRadius), -1, 0});
}

}  // namespace glossy
