#include "renderer/cli/scene_options.h"

#include "materials/core/input_error.h"

#include <cmath>
#include <sstream>
#include <vector>

namespace glossy::cli {

namespace {

Rgb parseRgb(const std::string& text, const std::string& option) {
  std::stringstream s(text);
  std::vector<double> v;
  std::string item;
  while (std::getline(s, item, ',')) {
    try {
      size_t used = 0;
      v.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(option + ": '" + text + "' is not a number or R,G,B");
    }
  }
  if (v.size() == 1) v.assign(3, v[0]);
  if (v.size() != 3) throw InputError(option + ": '" + text + "' is not a number or R,G,B");
  for (double x : v)
    if (!std::isfinite(x) || x < 0.0) throw InputError(option + ": radiance must be finite and >= 0, got '" + text + "'");
  return {v[0], v[1], v[2]};
}

}  // namespace

Environment environmentFromOptions(const std::string& file, const std::string& constant, double rotateDegrees) {
  if (!constant.empty()) return Environment::constant(parseRgb(constant, "--env-constant"));
  if (!file.empty()) return Environment::load(file, rotateDegrees);
  return Environment::makeDefault(rotateDegrees);
}

const Camera& cameraFromOptions(const SceneDescription& scene, const std::string& name, const std::string& scenePath) {
  if (scene.cameras.empty()) throw InputError(scenePath + ": the scene has no camera");
  if (name.empty()) return scene.cameras.front();
  for (const Camera& c : scene.cameras)
    if (c.name == name) return c;
  throw InputError(scenePath + ": no camera named '" + name + "'");
}

}  // namespace glossy::cli
