#include "renderer/app/scene_options.h"

#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "materials/core/text.h"
#include "renderer/camera/auto_camera.h"
#include "renderer/util/data_dir.h"
#include "renderer/util/digest.h"

#include <cmath>

namespace glossy::app {

namespace {

// Brighter than any sky by far, and dim enough that radiance times the brightest accepted BRDF peak stays
// finite in float.
constexpr double kMaxRadiance = 1e12;

Rgb parseRgb(const std::string& text, const std::string& option) {
  auto v = parseNumberList(text);
  if (v && v->size() == 1) v->assign(3, v->front());
  if (!v || v->size() != 3) throw InputError(option + ": '" + text + "' is not a number or R,G,B");
  for (double x : *v)
    if (!std::isfinite(x) || x < 0.0 || x > kMaxRadiance)
      throw InputError(option + ": radiance must be a finite number in [0, " + formatted("%g", kMaxRadiance) + "], got '" +
                       shortened(text) + "'");
  return {(*v)[0], (*v)[1], (*v)[2]};
}

}  // namespace

std::string SceneOptions::scenePath() const {
  return scene.empty() ? (dataDir() / "scenes/preview.gltf").string() : scene;
}

Environment SceneOptions::environment() const {
  if (!envConstant.empty()) return Environment::constant(parseRgb(envConstant, "--env-constant"));
  if (!env.empty()) return Environment::load(env, envRotate);
  return Environment::makeDefault(envRotate);
}

std::string SceneOptions::inputs(const SceneDescription& scene, const Environment& environment) const {
  std::string line = "scene=" + scene.source.string() + "; env=" + environment.description() + "; sceneDigest=" + scene.digest +
                     "; camera=" + (camera.empty() ? std::string("first") : camera) +
                     "; envDigest=" + (envConstant.empty() && !env.empty() ? fileDigest(env, "environment map") : std::string("none"));
  if (!envConstant.empty()) {
    const Rgb c = parseRgb(envConstant, "--env-constant");
    return line + formatted("; envConstant=%.17g,%.17g,%.17g", c.r, c.g, c.b);
  }
  return line + formatted("; envRotate=%.17g", envRotate);
}

Camera SceneOptions::cameraOf(const SceneDescription& description, double aspect) const {
  const std::string where = description.source.string();
  if (camera == "auto") return autoCamera(description, aspect);
  if (description.cameras.empty()) {
    if (!camera.empty()) throw InputError(where + ": the scene has no camera named '" + camera + "' (it has none; try --camera auto)");
    note(printableLine(where + " has no camera: framing it as --camera auto does"));
    return autoCamera(description, aspect);
  }
  if (camera.empty()) return description.cameras.front();
  for (const Camera& c : description.cameras)
    if (c.name == camera) return c;
  throw InputError(where + ": no camera named '" + camera + "'");
}

}  // namespace glossy::app
