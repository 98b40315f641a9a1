// A scene's lights, and the choice of one per light sample: in proportion to power (light.h), so that a
// bright window is sampled more often than a dim lamp, and the environment against the emitters by what
// it sends through the scene's bounds.
#pragma once

#include "materials/sampling/distribution.h"
#include "renderer/lights/light.h"

#include <memory>
#include <span>
#include <vector>

namespace glossy {

struct ChosenLight {
  const Light* light = nullptr;
  double probability = 0.0;  // of choosing it
  explicit operator bool() const { return light != nullptr; }
};

// Adds a light type to those of light_set.cpp's line, for every LightSet made after: how a program that
// links the renderer library (a test) brings a type of its own, in one line of the type's own file:
// `static const bool registered = registerLightType(myLights);`. The renderer's own types are listed in
// light_set.cpp instead, since a static library drops a file nothing refers to. Not thread-safe: call it
// before rendering (a static initializer is).
bool registerLightType(LightFactory* type);

class LightSet {
 public:
  // Every registered light type's lights in the scene (light_set.cpp).
  explicit LightSet(const LightSources& sources);

  // Whether choose(u) depends on u: more than one light has power.
  bool hasChoice() const { return lightsWithPower_ > 1; }
  // A light drawn by power with u in [0, 1); none if the scene has no light with power.
  ChosenLight choose(double u) const;
  // The surface light covering a hit's triangle, with its probability of being chosen; none if the
  // triangle emits nothing.
  ChosenLight at(const Hit& hit) const;
  // Whether a ray can hit a light: some surface emits.
  bool onSurfaces() const { return onSurfaces_; }
  // The lights a ray that leaves the scene sees, with their probabilities.
  std::span<const ChosenLight> distant() const { return distant_; }

 private:
  std::vector<std::unique_ptr<Light>> lights_;
  std::vector<ChosenLight> chosen_;  // each light with its probability
  Distribution1D power_;
  int lightsWithPower_ = 0;
  bool onSurfaces_ = false;
  std::vector<ChosenLight> distant_;
  std::vector<std::vector<int>> surface_;  // [mesh][triangle]: index into lights_, or −1
};

}  // namespace glossy
