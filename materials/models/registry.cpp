#include "materials/models/registry.h"

#include "materials/core/input_error.h"

#include <stdexcept>

namespace glossy {

namespace {

std::deque<ModelInfo>& models() {
  // A deque: findModel's pointers stay valid as models are registered.
  static std::deque<ModelInfo> all = []<class... M>(ModelList<M...>) { return std::deque<ModelInfo>{modelInfo<M>()...}; }(BuiltinModels{});
  return all;
}

std::string joined(const char* separator, auto&& part) {
  std::string s;
  for (const ModelInfo& m : models())
    if (const std::string p = part(m); !p.empty()) s += (s.empty() ? "" : separator) + p;
  return s;
}

}  // namespace

void registerModel(const ModelInfo& model) {
  if (findModel(model.name)) throw std::logic_error("a model named '" + std::string(model.name) + "' is already registered");
  models().push_back(model);
}

const std::deque<ModelInfo>& analyticModels() { return models(); }

const ModelInfo* findModel(std::string_view name) {
  for (const ModelInfo& m : models())
    if (m.name == name) return &m;
  return nullptr;
}

const ModelInfo& requireModel(std::string_view name, const std::string& context) {
  if (const ModelInfo* m = findModel(name)) return *m;
  throw InputError(context + ": unknown model '" + shortened(name) + "' (known: " + knownModelNames() + ")");
}

std::string knownModelNames() {
  return joined(", ", [](const ModelInfo& m) { return std::string(m.name); });
}

std::string modelConventions() {
  return joined("; ", [](const ModelInfo& m) {
    return m.conventions.empty() ? std::string() : std::string(m.name) + ": " + std::string(m.conventions);
  });
}

}  // namespace glossy
