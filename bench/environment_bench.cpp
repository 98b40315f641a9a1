// Nanoseconds per call of the environment light's hot calls, on 1 thread: sample(u), pdf(dir) and
// radianceAndPdf(dir), on directions sample() returns (the light samples' MIS pdfs) and on uniformly
// random directions (escaping BSDF rays). Prints the median of RUNS timings of each; asserts nothing.
// The batch forms are timed per lane, in batches of 8 (a packet) and 64 (a wave).
// The inputs are made before the clock starts, so only the calls are timed.
#include "bench/timing.h"
#include "renderer/lights/environment.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <random>
#include <vector>

using namespace glossy;

namespace {

// 2D Sobol' points (van der Corput and the second Sobol' dimension) with a random digital shift: the
// stratified u a renderer's light samples get, in the order of its sample indices.
std::vector<Vec2> sobolPoints(std::size_t n, std::mt19937_64& rng) {
  const uint32_t shift0 = uint32_t(rng()), shift1 = uint32_t(rng());
  std::vector<Vec2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    uint32_t a = 0, b = 0, v = 1u << 31;
    for (uint32_t index = uint32_t(i), bit = 0; index != 0; index >>= 1, ++bit, v ^= v >> 1)
      if (index & 1) a ^= 1u << (31 - bit), b ^= v;
    points[i] = {double(a ^ shift0) * 0x1p-32, double(b ^ shift1) * 0x1p-32};
  }
  return points;
}

template <class F>
double nsPerCall(std::size_t calls, F&& f) {
  return bench::seconds(f) * 1e9 / double(calls);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"glossy_environment_bench: ns per call of Environment::sample, pdf and radianceAndPdf"};
  std::string envPath;
  std::size_t count = 1u << 21;
  int runs = 5;
  app.add_option("--env", envPath, "A lat-long map (e.g. build/compare/sky.exr); default: the built-in sky");
  app.add_option("-n,--calls", count, "Calls per timing")->capture_default_str();
  app.add_option("--runs", runs, "Timings of each call; the median is printed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const bool fromFile = !envPath.empty() && std::filesystem::exists(envPath);
  const Environment env = fromFile ? Environment::load(envPath) : Environment::makeDefault();
  std::printf("environment: %s%s, %zu calls per timing, median of %d\n", env.description().c_str(),
              !envPath.empty() && !fromFile ? " (map not found)" : "", count, runs);

  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> uniform;
  const std::vector<Vec2> sobol = sobolPoints(count, rng);
  std::vector<Vec2> random(count);
  for (Vec2& u : random) u = {uniform(rng), uniform(rng)};
  std::vector<Vec3> sampled(count), uniformDirs(count), normals(count);
  const auto uniformDirection = [&] {
    const double z = 1.0 - 2.0 * uniform(rng), r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * uniform(rng);
    return Vec3(r * std::cos(phi), z, r * std::sin(phi));
  };
  // Every call is toward a surface, as the path tracer's are: normals uniform over the sphere.
  for (std::size_t i = 0; i < count; ++i) {
    normals[i] = uniformDirection();
    sampled[i] = env.sample(normals[i], random[i]).dir;
    uniformDirs[i] = uniformDirection();
  }
  // Shuffled like the rest so that neither set is walked in map order.
  std::shuffle(sampled.begin(), sampled.end(), rng);

  // Every result feeds a sum printed at the end, so no call can be optimised away.
  double sink = 0.0;
  auto timeSample = [&](const std::vector<Vec2>& us) {
    return nsPerCall(us.size(), [&] {
      double sum = 0.0;
      for (std::size_t i = 0; i < us.size(); ++i) {
        const Environment::Sample s = env.sample(normals[i], us[i]);
        sum += s.pdf + s.dir.x + s.radiance.g;
      }
      sink += sum;
    });
  };
  auto timePdf = [&](const std::vector<Vec3>& dirs) {
    return nsPerCall(dirs.size(), [&] {
      double sum = 0.0;
      for (std::size_t i = 0; i < dirs.size(); ++i) sum += env.pdf(normals[i], dirs[i]);
      sink += sum;
    });
  };
  auto timeRadianceAndPdf = [&](const std::vector<Vec3>& dirs) {
    return nsPerCall(dirs.size(), [&] {
      double sum = 0.0;
      for (std::size_t i = 0; i < dirs.size(); ++i) {
        double pdf = 0.0;
        sum += env.radianceAndPdf(normals[i], dirs[i], pdf).g + pdf;
      }
      sink += sum;
    });
  };
  auto timeRadiance = [&](const std::vector<Vec3>& dirs) {
    return nsPerCall(dirs.size(), [&] {
      double sum = 0.0;
      for (const Vec3& d : dirs) sum += env.radiance(d).g;
      sink += sum;
    });
  };

  // The batch forms, n lanes per call as the path tracer's waves use them; ns per lane.
  auto timeSampleBatch = [&](const std::vector<Vec2>& us, int n) {
    return nsPerCall(us.size(), [&] {
      bool want[Environment::kMaxBatch];
      std::fill(want, want + n, true);
      Environment::Sample out[Environment::kMaxBatch];
      double sum = 0.0;
      for (std::size_t first = 0; first + std::size_t(n) <= us.size(); first += std::size_t(n)) {
        env.sample(want, &normals[first], &us[first], out, n);
        for (int i = 0; i < n; ++i) sum += out[i].pdf + out[i].dir.x + out[i].radiance.g;
      }
      sink += sum;
    });
  };
  auto timeRadianceAndPdfBatch = [&](const std::vector<Vec3>& dirs, int n) {
    return nsPerCall(dirs.size(), [&] {
      bool want[Environment::kMaxBatch];
      std::fill(want, want + n, true);
      Rgb radiance[Environment::kMaxBatch];
      double pdf[Environment::kMaxBatch];
      double sum = 0.0;
      for (std::size_t first = 0; first + std::size_t(n) <= dirs.size(); first += std::size_t(n)) {
        env.radianceAndPdf(want, &normals[first], &dirs[first], radiance, pdf, n);
        for (int i = 0; i < n; ++i) sum += radiance[i].g + pdf[i];
      }
      sink += sum;
    });
  };

  struct Row {
    const char* name;
    std::function<double()> time;
    std::vector<double> ns;
  };
  std::vector<Row> rows{{"sample(u), Sobol' u", [&] { return timeSample(sobol); }, {}},
                        {"sample(u), random u", [&] { return timeSample(random); }, {}},
                        {"pdf(dir), sampled dirs", [&] { return timePdf(sampled); }, {}},
                        {"pdf(dir), uniform dirs", [&] { return timePdf(uniformDirs); }, {}},
                        {"radianceAndPdf, sampled dirs", [&] { return timeRadianceAndPdf(sampled); }, {}},
                        {"radianceAndPdf, uniform dirs", [&] { return timeRadianceAndPdf(uniformDirs); }, {}},
                        {"radiance(dir), uniform dirs", [&] { return timeRadiance(uniformDirs); }, {}},
                        {"sample, batches of 8, random u", [&] { return timeSampleBatch(random, 8); }, {}},
                        {"sample, batches of 64, random u", [&] { return timeSampleBatch(random, 64); }, {}},
                        {"radianceAndPdf, batches of 8, uniform dirs", [&] { return timeRadianceAndPdfBatch(uniformDirs, 8); }, {}},
                        {"radianceAndPdf, batches of 64, uniform dirs", [&] { return timeRadianceAndPdfBatch(uniformDirs, 64); }, {}}};
  for (Row& row : rows) row.time();  // warm-up: page faults, caches
  // Runs interleave the calls, so that a burst of load from other processes hits all of them alike.
  for (int run = 0; run < runs; ++run)
    for (Row& row : rows) row.ns.push_back(row.time());

  std::printf("| call | ns/call (median) | min | max |\n|---|---|---|---|\n");
  for (const Row& row : rows)
    std::printf("| %s | %.1f | %.1f | %.1f |\n", row.name, bench::median(row.ns), *std::min_element(row.ns.begin(), row.ns.end()),
                *std::max_element(row.ns.begin(), row.ns.end()));
  std::printf("(checksum %.6g)\n", sink);
  return 0;
}
