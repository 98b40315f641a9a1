// The models a parameter file may name, with their parameter declarations: the built-in ones
// (builtin_models.h), then any registered at run time. Everything that lists models — material files,
// `--fit` and `--model` validation, the fitter, the sheets' panels — asks here.
//
// Adding a model: write its header (eval/sample/pdf + kName/kLabel/kParams/fromParams, optionally
// kShortLabel, kConventions and kFitCost) and add it to BuiltinModels in builtin_models.h. A model outside the
// library (a plugin, a test) is registered instead: registerModel(modelInfo<M>()).
#pragma once

#include "materials/models/brdf.h"

#include <deque>
#include <span>
#include <string>
#include <string_view>

namespace glossy {

struct ModelInfo {
  std::string_view name;        // as written in parameter files: "cook-torrance"
  std::string_view label;       // for people: "Cook-Torrance"
  std::string_view shortLabel;  // for a sheet panel's label: "CT"
  std::string_view conventions; // how the published formula is read, for image metadata; may be empty
  std::span<const ParamSpec> params;
  Brdf (*make)(const ParamSet&);
  double fitCost = 1.0;  // a fit's expected cost, in units of a Microfacet fit (kFitCost; docs/cluster.md)
};

template <class M>
ModelInfo modelInfo() {
  ModelInfo info{M::kName, M::kLabel, M::kLabel, {}, M::kParams, [](const ParamSet& p) -> Brdf { return M::fromParams(p); }};
  if constexpr (requires { M::kShortLabel; }) info.shortLabel = M::kShortLabel;
  if constexpr (requires { M::kConventions; }) info.conventions = M::kConventions;
  if constexpr (requires { M::kFitCost; }) info.fitCost = M::kFitCost;
  return info;
}

// Adds a model after the others. What its views point to must outlive the registry (static data). Not
// synchronised with the lookups: register before anything reads a parameter file or renders. A name
// already taken is a logic error.
void registerModel(const ModelInfo& model);

// The built-in models in the order of the supplement's comparison grid, then Lambertian, then those
// registered, in the order they were.
const std::deque<ModelInfo>& analyticModels();
const ModelInfo* findModel(std::string_view name);  // nullptr if unknown
// The model, or InputError "<context>: unknown model 'name' (known: ...)".
const ModelInfo& requireModel(std::string_view name, const std::string& context);
std::string knownModelNames();                      // "microfacet, smooth, ..." for error messages
// Every model's conventions, "model: ...; model: ...", as the images' glossy:conventions records them.
std::string modelConventions();

}  // namespace glossy
