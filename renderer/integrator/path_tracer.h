// Rendering an image by path tracing (reference_path.cpp says what a path does in plain code; the wave,
// path_vertex.h, does it for many paths at once, the default), or the panels of a sheet together. Depth follows Mitsuba 3:
// maxDepth counts path segments, so 1 shows only directly visible emitters, 2 adds direct lighting, 3 one
// indirect bounce, and so on.
#pragma once

#include "materials/models/brdf.h"
#include "renderer/image/exr_image.h"
#include "renderer/lights/environment.h"
#include "renderer/lights/light_set.h"
#include "renderer/scene/embree_scene.h"
#include "renderer/util/job_control.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glossy {

// The most light samples a vertex takes (RenderSettings::lightSamples), and the most BSDF samples a first
// vertex takes (light_count.h: a sharp lobe's).
constexpr int kMaxLightSamples = 8;
constexpr int kMaxBsdfSamples = 24;

struct RenderSettings {
  int width = 512, height = 512;
  int spp = 64;
  int firstSample = 0;    // samples of each pixel before this pass: seeds a progressive pass's own pattern
  int maxDepth = 8;
  int rouletteDepth = 4;  // Russian roulette from this depth on
  // Light samples at a camera path's first vertex (path_vertex.h), at most, 1 … kMaxLightSamples; one at
  // the others. With lightSamplesPerBrdf each BRDF takes its own count up to this, and its own count of
  // BSDF samples there (light_count.h; a sheet's panels the most of theirs), else every first vertex takes
  // this many, and bsdfSamples BSDF samples (1 … kMaxBsdfSamples) where it is on a sheet's object
  // (everywhere outside sheets), else one.
  int lightSamples = 4;
  bool lightSamplesPerBrdf = true;
  int bsdfSamples = 1;
  uint32_t seed = 0;
  int threads = 0;        // 0 = all cores
  bool progress = true;
  // Sample every BRDF's cosine lobe instead of its own (exact pdf either way): only to measure what lobe
  // sampling is worth.
  bool cosineBrdfSampling = false;
  // The reference path tracer (reference_path.h) instead of the wave: one light and one BSDF sample per
  // vertex, its own random numbers, each panel of a sheet on its own. The same image in expectation, with
  // more noise, more slowly: the oracle the wave is tested against.
  bool reference = false;
  // Optional, width × height: only the pixels marked here are traced (the others stay black), for a render
  // whose figures look at part of the image (a sheet's noise-floor row: the object's pixels).
  const std::vector<char>* pixels = nullptr;
  // Optional: counts each finished tile in `done` and stops early, leaving the image unfinished, when
  // cancelled. The caller owns it and sets its total (renderTiles).
  JobControl* control = nullptr;
};

// How many tiles an image of this size is rendered in: what JobControl::done counts per image.
uint64_t renderTiles(int width, int height);

// What the integrator needs of a scene, built once: the BVH, the BRDF of each scene material, the
// environment (may be null). Its other lights are the scene's emissive triangles.
struct RenderScene {
  const SceneDescription* description;
  const EmbreeScene* bvh;
  std::vector<Brdf> brdfs;  // per SceneDescription::materials entry
  Brdf defaultBrdf = Lambertian{Rgb(0.5)};
  const Environment* environment;
  // Per SceneDescription::meshes entry: part of a sheet's object, the meshes whose BRDF differs from panel
  // to panel (renderPanels). Empty outside sheets.
  std::vector<bool> objectMeshes = {};

  const Brdf& brdfOf(uint32_t mesh) const {
    const int m = description->meshes[mesh].material;
    return m < 0 ? defaultBrdf : brdfs[size_t(m)];
  }
  bool isObject(uint32_t mesh) const { return mesh < objectMeshes.size() && objectMeshes[mesh]; }
};

// The light and BSDF samples a camera path's first vertex takes, per scene material (index + 1; 0 the default
// BRDF): the same in every panel of a sheet (renderPanels), so that the panels share the draws and the
// shadow rays.
struct LightCounts {
  std::vector<int> taken;
  std::vector<int> bsdf;
};

// What a path tracer works from.
struct PathContext {
  const RenderScene& scene;
  const RenderSettings& settings;
  const LightSet& lights;
  LightCounts counts = {};

  // The light samples a vertex on the mesh at this depth takes, and its BSDF samples.
  int lightSamplesAt(uint32_t mesh, int depth) const {
    return depth == 1 ? counts.taken[size_t(scene.description->meshes[mesh].material + 1)] : 1;
  }
  int bsdfSamplesAt(uint32_t mesh, int depth) const {
    return depth == 1 ? counts.bsdf[size_t(scene.description->meshes[mesh].material + 1)] : 1;
  }
};

struct RenderStats {
  uint64_t droppedSamples = 0;  // non-finite path contributions, discarded (per panel, summed)
  uint64_t objectPaths = 0;     // renderPanels: paths that reached the object, where the panels part ways
  double seconds = 0.0;
};

RgbImage render(const RenderScene& scene, const Camera& camera, const RenderSettings& settings, RenderStats& stats);

// The panels of a sheet, rendered together: panels[p] is the scene with panel p's BRDF on the object
// (RenderScene::objectMeshes, the same in every panel). Sample j of pixel i follows one path in every
// panel up to its first vertex on the object: the camera ray, the backdrop's vertices, their light samples
// and shadow rays, and that vertex's own draws, light sample and shadow ray are computed once. From there
// each panel continues with its own BRDF and the same draws, dimension for dimension. So each panel is,
// sample for sample, the image render() makes of its scene, while a path that never meets the object is
// traced once and shared whole.
std::vector<RgbImage> renderPanels(std::span<const RenderScene> panels, const Camera& camera, const RenderSettings& settings,
                                   RenderStats& stats);

}  // namespace glossy
