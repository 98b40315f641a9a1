#include "renderer/scene/material_binding.h"

#include "materials/core/input_error.h"
#include "materials/models/registry.h"
#include "renderer/util/data_dir.h"

#include <cctype>

namespace glossy {

namespace {

std::filesystem::path findMaterialFile(const std::string& name, const std::filesystem::path& sceneDir) {
  const std::filesystem::path p = name;
  std::error_code ec;
  for (const auto& candidate : {sceneDir / p, p, dataDir() / p})
    if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
  return sceneDir / p;  // let the loader report it, naming the path
}

}  // namespace

BrdfChoice brdfFromMaterialFile(const std::filesystem::path& file, const std::string& fitText) {
  const MaterialFile m = loadMaterialFile(file);
  const FitId id = FitId::parse(fitText, file.string() + ": fit");
  const Fit* fit = m.find(id);
  if (!fit) throw InputError(file.string() + ": has no " + id.str() + " fit");
  return {makeBrdf(*fit), file.string(), id.str(), *fit};
}

std::vector<std::pair<std::string, std::string>> choiceAttributes(const std::vector<Fit>& fits) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const ModelInfo& model : analyticModels())
    for (const ParamSpec& spec : model.params) {
      if (spec.kind != ParamKind::Choice) continue;
      std::string key = "glossy:";
      for (size_t i = 0; i < model.name.size(); ++i)  // cook-torrance → cookTorrance
        if (model.name[i] != '-') key += i > 0 && model.name[i - 1] == '-' ? char(std::toupper(model.name[i])) : model.name[i];
      key += char(std::toupper(spec.key[0])) + std::string(spec.key.substr(1));
      std::string values;
      for (const Fit& f : fits)
        if (const std::string v = f.id.model == model.name ? f.params.choice(spec.key, model.params) : ""; !v.empty() && values.find(v) == std::string::npos)
          values.append(values.empty() ? "" : ", ").append(v);
      out.push_back({key, values.empty() ? std::string(spec.choices.front()) : values});
    }
  return out;
}

MaterialBinding bindMaterials(const SceneDescription& scene, const std::optional<BrdfChoice>& override) {
  MaterialBinding b;
  if (override && override->fitted) b.fits.push_back(*override->fitted);
  for (const SceneMaterial& m : scene.materials) {
    if (m.isEmissive()) {
      b.brdfs.push_back(Lambertian{Rgb(0.0)});
    } else if (override) {
      b.brdfs.push_back(override->brdf);
    } else if (!m.glossyMaterial.empty()) {
      BrdfChoice c;
      try {
        c = brdfFromMaterialFile(findMaterialFile(m.glossyMaterial, scene.source.parent_path()), m.glossyFit);
      } catch (const InputError& e) {
        // Name the scene and its material too: the parameter file alone does not say who asked for it.
        throw InputError(scene.source.string() + ": material '" + m.name + "' (extras.glossy): " + e.what());
      }
      b.brdfs.push_back(c.brdf);
      b.bindings.push_back(c.material + " " + c.fit);
      b.commonFit = b.bindings.size() == 1 || b.commonFit == c.fit ? c.fit : "";
      b.fits.push_back(*c.fitted);
    } else {
      b.brdfs.push_back(Lambertian{m.baseColor});
    }
  }
  return b;
}

}  // namespace glossy
