// Rendering an image by path tracing (path_reference.cpp says what a path does; path_wave.cpp does the
// same for many paths at once, the default). Depth follows Mitsuba 3: maxDepth counts path segments, so 1
// shows only directly visible emitters, 2 adds direct lighting, 3 one indirect bounce, and so on.
#pragma once

#include "materials/models/brdf.h"
#include "renderer/image/exr_image.h"
#include "renderer/lights/environment.h"
#include "renderer/scene/embree_scene.h"

#include <cstdint>
#include <vector>

namespace glossy {

struct RenderSettings {
  int width = 512, height = 512;
  int spp = 64;
  int firstSample = 0;    // samples of each pixel before this pass: seeds a progressive pass's own pattern
  int maxDepth = 8;
  int rouletteDepth = 4;  // Russian roulette from this depth on
  uint32_t seed = 0;
  int threads = 0;        // 0 = all cores
  bool progress = true;
  // Sample every BRDF's cosine lobe instead of its own (exact pdf either way): only to measure what lobe
  // sampling is worth.
  bool cosineBrdfSampling = false;
  // One path at a time (path_reference.cpp) instead of waves: the same image, bit for bit, more slowly.
  bool reference = false;
};

// What the integrator needs of a scene, built once: the BVH, the BRDF of each scene material, the
// environment (may be null). Its other lights are the scene's emissive triangles.
struct RenderScene {
  const SceneDescription* description;
  const EmbreeScene* bvh;
  std::vector<Brdf> brdfs;  // per SceneDescription::materials entry
  Brdf defaultBrdf = Lambertian{Rgb(0.5)};
  const Environment* environment;

  const Brdf& brdfOf(uint32_t mesh) const {
    const int m = description->meshes[mesh].material;
    return m < 0 ? defaultBrdf : brdfs[size_t(m)];
  }
};

struct RenderStats {
  uint64_t droppedSamples = 0;  // non-finite path contributions, discarded
  double seconds = 0.0;
};

RgbImage render(const RenderScene& scene, const Camera& camera, const RenderSettings& settings, RenderStats& stats);

}  // namespace glossy
