// Which BRDF each scene material renders with: the command line's override, the glTF material's
// extras.glossy binding (a parameter file and a fit), or its baseColor as a Lambertian.
#pragma once

#include "materials/models/brdf.h"
#include "materials/params/material_file.h"
#include "renderer/scene/scene.h"

#include <optional>
#include <string>
#include <vector>

namespace glossy {

struct BrdfChoice {
  Brdf brdf;
  std::string material;  // file it came from, for metadata
  std::string fit;       // MODEL:METRIC or "measured"
  std::optional<Fit> fitted;  // the parameters it was made from, if any: their choices go into the metadata
};

// Loads `fitText` (MODEL:METRIC) of a parameter file; InputError naming the file if absent or bad.
BrdfChoice brdfFromMaterialFile(const std::filesystem::path& file, const std::string& fitText);
// The choices the fits make (ParamKind::Choice parameters, such as smooth's fresnel), as image metadata
// records them: for each model that declares one, "glossy:<model><Key>" (glossy:smoothFresnel) → the values
// the fits of that model take, ", "-joined, or the choice's default when none of them is of that model.
std::vector<std::pair<std::string, std::string>> choiceAttributes(const std::vector<Fit>& fits);

struct MaterialBinding {
  std::vector<Brdf> brdfs;            // per SceneDescription::materials entry
  std::vector<std::string> bindings;  // "file fit" of each extras.glossy binding used
  std::string commonFit;              // the fit every extras.glossy binding names, if they agree; else ""
  std::vector<Fit> fits;              // the fits rendered: the override's, else the bindings'
};

// Emissive materials keep a black Lambertian (they reflect nothing). A binding's material path is looked
// up beside the scene file, then in the working folder, then in the source tree.
MaterialBinding bindMaterials(const SceneDescription& scene, const std::optional<BrdfChoice>& override);

}  // namespace glossy
