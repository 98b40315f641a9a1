// glossy_compare: glossy's side of the glossy-vs-Mitsuba benchmark (bench/mitsuba/compare.py drives it).
//
// It loads a glTF scene and a lat-long environment once (scene load and BVH build are never timed), then
// answers commands on stdin, one line each, so the driver can interleave glossy's and Mitsuba's runs in one
// invocation while neither pays a process start or a scene load per run:
//
//   render SPP SEED THREADS OUT     render; write the EXR to OUT unless OUT is "-"
//                                   → "ok SECONDS DROPPED CPU_SECONDS"   (SECONDS: the render call's wall
//                                   time; CPU_SECONDS: the process's CPU time over it, all threads)
//   rays SPP THREADS RUNS           record every ray of one render, then time RUNS renders and RUNS replays
//                                   of the recorded rays through raw Embree (each after a warm-up), one ray
//                                   at a time and in the render's own packets
//                                   → "ok RAYS SAMPLES PT_SECONDS RAW_SECONDS RAW_PACKET_SECONDS" (medians)
//   dumprays SPP FILE               record every ray of one render and write them to FILE, 8 little-endian
//                                   float32 per ray: origin, direction, tfar, 1 for a shadow ray else 0 (for
//                                   timing another renderer's traversal on the same rays) → "ok RAYS"
//   quit
//
// An error answers "error MESSAGE". `glossy_compare --write-sky FILE` writes glossy's built-in procedural
// sky as a float EXR (the map both renderers load) and exits. --env-constant stands in for --env (the
// efficiency table's constant light, Environment::constant); --measured renders every mesh with a MERL
// table and glossy's tabulated sampler for it (Measured), as `glossy render --measured` does.
#include "bench/ray_replay.h"
#include "renderer/util/atomic_file.h"
#include "materials/merl/merl_table.h"
#include "renderer/image/exr_image.h"
#include "renderer/integrator/light_count.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/lights/default_sky.h"
#include "renderer/scene/material_binding.h"

#include <CLI/CLI.hpp>

#include <sys/resource.h>

#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

using namespace glossy;
using namespace glossy::bench;

namespace {

// User + system CPU time of the whole process (every thread), seconds.
double processCpuSeconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

int writeSky(const std::string& path) {
  const LatLongImage sky = makeDefaultSky();
  RgbImage image(sky.width, sky.height);
  for (int row = 0; row < sky.height; ++row)
    for (int column = 0; column < sky.width; ++column)
      for (int c = 0; c < 3; ++c) image.at(column, row)[c] = sky.at(column, row)[c];
  writeExr(path, image, {{"glossy:env", std::string("default sky (renderer/lights/default_sky.cpp)")}}, PixelType::Float);
  return 0;
}

// Every ray of one render (rendering is deterministic: another render with these settings casts the same).
RecordedRays recordRays(EmbreeScene& bvh, const RenderScene& scene, const Camera& camera, const RenderSettings& settings) {
  RenderStats stats;
  Recorder recorder;
  bvh.setRecorder(&recorder);
  render(scene, camera, settings, stats);
  bvh.setRecorder(nullptr);
  return recorder.take();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"glossy_compare: glossy's side of bench/mitsuba/compare.py (commands on stdin; see the source)"};
  std::string scenePath, envPath, skyOut, measuredPath;
  double envConstant = -1.0;
  int width = 256, height = 256, maxDepth = 3;
  app.add_option("--scene", scenePath, "glTF scene (its first camera, its extras.glossy bindings)");
  auto* envOpt = app.add_option("--env", envPath, "Lat-long environment map (.exr, .hdr)");
  app.add_option("--env-constant", envConstant, "Constant environment radiance instead of --env")
      ->excludes(envOpt)->check(CLI::NonNegativeNumber);
  app.add_option("--measured", measuredPath, "MERL table (.binary or .binary.xz) for every mesh instead of its binding");
  app.add_option("--width", width)->capture_default_str();
  app.add_option("--height", height)->capture_default_str();
  app.add_option("--max-depth", maxDepth, "Path segments at most (3 = one indirect bounce)")->capture_default_str();
  app.add_option("--write-sky", skyOut, "Write the built-in procedural sky as an EXR and exit");
  int lightSamples = RenderSettings{}.lightSamples;
  app.add_option("--light-samples", lightSamples, "Light samples at a path's first vertex, at most (each BRDF takes its own)")
      ->capture_default_str()->check(CLI::Range(1, kMaxLightSamples));
  bool fixedLightSamples = false;
  app.add_flag("--fixed-light-samples", fixedLightSamples, "Every first vertex takes --light-samples, whatever its BRDF");
  CLI11_PARSE(app, argc, argv);

  try {
    if (!skyOut.empty()) return writeSky(skyOut);
    if (scenePath.empty() || (envPath.empty() && envConstant < 0.0)) {
      std::cerr << "glossy_compare: --scene and --env (or --env-constant) are required\n";
      return 2;
    }
    const SceneDescription description = loadGltf(scenePath);
    std::optional<BrdfChoice> override;
    if (!measuredPath.empty())
      override = BrdfChoice{Measured{std::make_shared<const MerlTable>(MerlTable::load(measuredPath))}, measuredPath, "measured", std::nullopt};
    MaterialBinding binding = bindMaterials(description, override);
    if (override) binding.bindings.push_back(measuredPath + " measured");
    const Environment environment = envPath.empty() ? Environment::constant(Rgb(envConstant)) : Environment::load(envPath);
    EmbreeScene bvh(description);
    const RenderScene scene{&description, &bvh, std::move(binding.brdfs), Lambertian{Rgb(0.5)}, &environment};
    const Camera& camera = description.cameras.at(0);
    std::string bound;
    for (const auto& b : binding.bindings) bound += (bound.empty() ? "" : "; ") + b;
    for (const Brdf& brdf : scene.brdfs)
      bound += "; light samples " + std::to_string(fixedLightSamples ? lightSamples : lightSamplesFor(brdf, lightSamples)) +
               " (share " + std::to_string(lightCarriedShare(brdf)) + ")";
    std::cout << "ready " << (bound.empty() ? "scene base colours" : bound) << std::endl;

    RenderSettings base;
    base.width = width;
    base.height = height;
    base.maxDepth = maxDepth;
    base.lightSamples = lightSamples;
    base.lightSamplesPerBrdf = !fixedLightSamples;
    base.progress = false;

    std::string line;
    while (std::getline(std::cin, line)) {
      std::istringstream in(line);
      std::string command;
      in >> command;
      try {
        if (command == "quit") break;
        if (command == "render") {
          RenderSettings settings = base;
          std::string out;
          if (!(in >> settings.spp >> settings.seed >> settings.threads >> out)) throw std::runtime_error("usage: render SPP SEED THREADS OUT");
          RenderStats stats;
          const double cpuStart = processCpuSeconds();
          const RgbImage image = render(scene, camera, settings, stats);
          const double cpu = processCpuSeconds() - cpuStart;
          if (out != "-")
            writeExr(out, image,
                     {{"glossy:spp", settings.spp}, {"glossy:seed", int(settings.seed)}, {"glossy:maxDepth", maxDepth},
                      {"glossy:renderSeconds", float(stats.seconds)}, {"glossy:scene", scenePath}, {"glossy:env", environment.description()}});
          std::printf("ok %.9g %llu %.6g\n", stats.seconds, static_cast<unsigned long long>(stats.droppedSamples), cpu);
        } else if (command == "rays") {
          RenderSettings settings = base;
          int runs = 5;
          if (!(in >> settings.spp >> settings.threads >> runs) || runs < 1) throw std::runtime_error("usage: rays SPP THREADS RUNS");
          const RecordedRays rays = recordRays(bvh, scene, camera, settings);
          RenderStats stats;
          render(scene, camera, settings, stats);  // warm-up
          const double pt = medianSeconds(runs, [&] { render(scene, camera, settings, stats); });
          const double raw = replaySeconds(bvh, rays, Replay::OneRayAtATime, settings.threads, runs);
          const double rawPackets = replaySeconds(bvh, rays, Replay::AsRecorded, settings.threads, runs);
          std::printf("ok %zu %.17g %.9g %.9g %.9g\n", rays.rays, double(width) * height * settings.spp, pt, raw, rawPackets);
        } else if (command == "dumprays") {
          RenderSettings settings = base;
          std::string out;
          if (!(in >> settings.spp >> out)) throw std::runtime_error("usage: dumprays SPP FILE");
          settings.threads = 1;
          const RecordedRays rays = recordRays(bvh, scene, camera, settings);
          std::vector<float> records;
          records.reserve(rays.rays * 8);
          for (const RecordedQuery& q : rays.queries)
            for (int i = 0; i < kPacketSize; ++i)
              if (q.valid[i]) {
                const RTCRay& r = q.rays[i];
                records.insert(records.end(), {r.org_x, r.org_y, r.org_z, r.dir_x, r.dir_y, r.dir_z, r.tfar,
                                               q.shadow ? 1.0f : 0.0f});
              }
          writeFileAtomically(out, std::string_view(reinterpret_cast<const char*>(records.data()),
                                                    records.size() * sizeof(float)));
          std::printf("ok %zu\n", rays.rays);
        } else {
          throw std::runtime_error("unknown command '" + command + "'");
        }
      } catch (const std::exception& e) {
        std::printf("error %s\n", e.what());
      }
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::cerr << "glossy_compare: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
