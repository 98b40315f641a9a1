#include "renderer/lights/light_set.h"

#include <cmath>

namespace glossy {

// The light types, each defined in its own file under renderer/lights/. Adding a type adds its factory's
// name to this line.
LightFactory environmentLight, emissiveTriangles, pointLights, spotLights, directionalLights;
static LightFactory* const kLightTypes[] = {environmentLight, emissiveTriangles, pointLights, spotLights, directionalLights};

namespace {
std::vector<LightFactory*>& registeredTypes() {
  static std::vector<LightFactory*> types;
  return types;
}
}  // namespace

bool registerLightType(LightFactory* type) {
  registeredTypes().push_back(type);
  return true;
}

LightSet::LightSet(const LightSources& sources) {
  std::vector<FoundLight> found;
  for (LightFactory* type : kLightTypes) type(sources, found);
  for (LightFactory* type : registeredTypes()) type(sources, found);
  surface_.resize(sources.scene.meshes.size());
  std::vector<double> powers;
  for (FoundLight& f : found) {
    if (f.mesh >= 0) {
      std::vector<int>& triangles = surface_[size_t(f.mesh)];
      if (triangles.size() <= f.triangle) triangles.resize(size_t(f.triangle) + 1, -1);
      triangles[f.triangle] = int(lights_.size());
      onSurfaces_ = true;
    }
    const double power = f.light->power();
    powers.push_back(std::isfinite(power) && power > 0.0 ? power : 0.0);
    lightsWithPower_ += powers.back() > 0.0;
    lights_.push_back(std::move(f.light));
  }
  if (lights_.empty()) return;
  power_ = Distribution1D(powers);
  for (size_t i = 0; i < lights_.size(); ++i) {
    chosen_.push_back({lights_[i].get(), lightsWithPower_ > 0 ? power_.discreteProbability(i) : 0.0});
    if (lights_[i]->distant()) distant_.push_back(chosen_.back());
  }
}

ChosenLight LightSet::choose(double u) const {
  if (lightsWithPower_ == 0) return {};
  return chosen_[power_.sampleDiscrete(u)];
}

ChosenLight LightSet::at(const Hit& hit) const {
  const std::vector<int>& triangles = surface_[hit.mesh];
  if (hit.triangle >= triangles.size() || triangles[hit.triangle] < 0) return {};
  return chosen_[size_t(triangles[hit.triangle])];
}

}  // namespace glossy
