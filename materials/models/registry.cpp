#include "materials/models/registry.h"

#include <array>

namespace glossy {

namespace {

template <class M>
constexpr ModelInfo infoOf() {
  return {M::kName, M::kLabel, M::kParams, [](const ParamSet& p) -> Brdf { return M::fromParams(p); }};
}
template <class... M>
constexpr std::array<ModelInfo, sizeof...(M)> infoOf(ModelList<M...>) {
  return {infoOf<M>()...};
}

constexpr auto kModels = infoOf(BuiltinModels{});

}  // namespace

std::span<const ModelInfo> analyticModels() { return kModels; }

const ModelInfo* findModel(std::string_view name) {
  for (const ModelInfo& m : kModels)
    if (m.name == name) return &m;
  return nullptr;
}

std::string knownModelNames() {
  std::string s;
  for (const ModelInfo& m : kModels) {
    if (!s.empty()) s += ", ";
    s += m.name;
  }
  return s;
}

}  // namespace glossy
