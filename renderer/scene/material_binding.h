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
  std::string smoothFresnel = "projected";
};

// Loads `fitText` (MODEL:METRIC) of a parameter file; InputError naming the file if absent or bad.
BrdfChoice brdfFromMaterialFile(const std::filesystem::path& file, const std::string& fitText);
// The Fresnel angle a smooth fit renders with, "projected" or "vh", as metadata records it; "" for other models.
std::string smoothFresnelOf(const Fit& fit);

struct MaterialBinding {
  std::vector<Brdf> brdfs;            // per SceneDescription::materials entry
  std::vector<std::string> bindings;  // "file fit" of each extras.glossy binding used
  std::string commonFit;              // the fit every extras.glossy binding names, if they agree; else ""
  std::string smoothFresnel = "projected";
};

// Emissive materials keep a black Lambertian (they reflect nothing). A binding's material path is looked
// up beside the scene file, then in the working folder, then in the source tree.
MaterialBinding bindMaterials(const SceneDescription& scene, const std::optional<BrdfChoice>& override);

}  // namespace glossy
