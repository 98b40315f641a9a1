#include "renderer/scene/material_binding.h"

#include "materials/core/input_error.h"
#include "renderer/util/data_dir.h"

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
  BrdfChoice c{makeBrdf(*fit), file.string(), id.str()};
  if (id.model == Smooth::kName) c.smoothFresnel = smoothFresnelOf(*fit);
  return c;
}

std::string smoothFresnelOf(const Fit& fit) {
  return fit.id.model == Smooth::kName ? fit.params.choice("fresnel", Smooth::kParams) : "";
}

MaterialBinding bindMaterials(const SceneDescription& scene, const std::optional<BrdfChoice>& override) {
  MaterialBinding b;
  if (override) b.smoothFresnel = override->smoothFresnel;
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
      if (c.fit.rfind("smooth:", 0) == 0) b.smoothFresnel = c.smoothFresnel;
    } else {
      b.brdfs.push_back(Lambertian{m.baseColor});
    }
  }
  return b;
}

}  // namespace glossy
