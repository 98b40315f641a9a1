// One `glossy render` without the command line: what to render and how, and the image with the metadata
// its EXR records. The command line and the Python module (renderer/python/) both run it, so the two make
// the same image, bit for bit.
#pragma once

#include "renderer/app/scene_options.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/scene/material_binding.h"

#include <optional>
#include <string>
#include <vector>

namespace glossy::app {

struct RenderJob {
  SceneOptions scene;
  // The object's BRDF: a material's fit, measured data, or one given as it is (`brdf`); none of them: the
  // scene's own bindings.
  std::string material, fit, measured, merlDir;
  std::optional<BrdfChoice> brdf;
  std::string brdfSampling = "lobe";  // or "cosine"
  RenderSettings settings;
};

struct RenderedImage {
  RgbImage image;
  std::vector<ImageAttribute> metadata;  // glossy:* as `glossy render` writes them
  RenderStats stats;
};

// What a render and a sheet both record of how they were made (glossy:*): the path tracer's settings, the scene and its lighting, the models' conventions, the samples dropped, the seconds
// and glossy's version.
std::vector<ImageAttribute> madeWith(const RenderSettings& s, const std::string& scene, const std::string& env,
                                     uint64_t droppedSamples, double seconds);

// Loads everything first (InputError naming the file or option), then renders. With settings.control
// cancelled the image is unfinished: the caller discards it.
RenderedImage renderImage(const RenderJob& job);

}  // namespace glossy::app
