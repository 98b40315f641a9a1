// Throughput benchmark (prints figures, asserts nothing): path tracing vs raw Embree on the same rays.
//
// For each scene the renderer runs once with a recorder that keeps every ray it casts. Rendering is
// deterministic, so timed runs cast exactly those rays; replaying them through rtcIntersect1/rtcOccluded1
// alone gives the raw rate for the same ray distribution, and the ratio is what shading costs.
#include "bench/ray_replay.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/scene/material_binding.h"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace glossy;
using namespace glossy::bench;

int main(int argc, char** argv) {
  CLI::App app{"glossy_bench: path-tracing throughput beside raw Embree throughput on the same rays"};
  int size = 256, spp = 16, runs = 5, maxDepth = 3;
  app.add_option("--size", size, "Image width and height")->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel")->capture_default_str();
  app.add_option("--runs", runs, "Timed runs per figure (the median is reported)")->capture_default_str();
  app.add_option("--max-depth", maxDepth, "Path segments at most (3 = one indirect bounce)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::printf("glossy %s  %dx%d, %d spp, max depth %d, default sky, median of %d runs\n\n", GLOSSY_VERSION, size, size, spp,
              maxDepth, runs);
  std::printf("%-12s %7s %14s %14s %16s %9s %16s %9s %10s\n", "scene", "threads", "samples/s", "PT rays/s", "raw 1-ray rays/s",
              "PT/raw", "raw packet rays/s", "PT/raw", "rays/spl");
  for (const char* name : {"sphere", "preview"}) {
    const SceneDescription description = loadGltf(std::filesystem::path(GLOSSY_SOURCE_DIR) / "scenes" / (std::string(name) + ".gltf"));
    MaterialBinding binding = bindMaterials(description, std::nullopt);
    const Environment environment = Environment::makeDefault();
    EmbreeScene bvh(description);
    const RenderScene scene{&description, &bvh, std::move(binding.brdfs), Lambertian{Rgb(0.5)}, &environment};
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.spp = spp;
    settings.maxDepth = maxDepth;
    settings.progress = false;
    RenderStats stats;

    Recorder recorder;
    bvh.setRecorder(&recorder);
    render(scene, description.cameras.front(), settings, stats);
    bvh.setRecorder(nullptr);
    const RecordedRays rays = recorder.take();
    const double samples = double(size) * size * spp;

    double samplesPerSecond[3] = {};
    for (int threads : {1, 2}) {
      settings.threads = threads;
      render(scene, description.cameras.front(), settings, stats);  // warm-up
      const double pt = medianSeconds(runs, [&] { render(scene, description.cameras.front(), settings, stats); });
      const double raw = replaySeconds(bvh, rays, Replay::OneRayAtATime, threads, runs);
      const double rawPackets = replaySeconds(bvh, rays, Replay::AsRecorded, threads, runs);
      samplesPerSecond[threads] = samples / pt;
      const double n = double(rays.rays);
      std::printf("%-12s %7d %14.3g %14.3g %16.3g %8.0f%% %16.3g %8.0f%% %10.2f\n", name, threads, samples / pt, n / pt, n / raw,
                  100.0 * raw / pt, n / rawPackets, 100.0 * rawPackets / pt, n / samples);
    }
    std::printf("%-12s scaling 1 -> 2 threads: %.2fx\n", name, samplesPerSecond[2] / samplesPerSecond[1]);
  }
  std::printf("\nPT/raw: the path tracer's ray rate as a share of raw Embree's on the same rays (100%% = shading is free):\n"
              "raw 1-ray traces them one at a time, raw packet as the path tracer grouped them.\n");
  return 0;
}
