// The analytic models a parameter file may name, with their parameter declarations. Adding a model:
// write its header (eval/sample/pdf + kName/kLabel/kParams/fromParams) and add it to BuiltinModels in
// builtin_models.h.
#pragma once

#include "materials/models/brdf.h"

#include <span>
#include <string_view>

namespace glossy {

struct ModelInfo {
  std::string_view name;   // as written in parameter files: "cook-torrance"
  std::string_view label;  // for people: "Cook-Torrance"
  std::span<const ParamSpec> params;
  Brdf (*make)(const ParamSet&);
};

// In the order of the supplement's comparison grid (Microfacet, Smooth, Ashikhmin-Shirley, Cook-Torrance),
// then Lambertian.
std::span<const ModelInfo> analyticModels();
const ModelInfo* findModel(std::string_view name);  // nullptr if unknown
std::string knownModelNames();                      // "microfacet, smooth, ..." for error messages

}  // namespace glossy
