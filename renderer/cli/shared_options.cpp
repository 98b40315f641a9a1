// The options several subcommands share: the scene's (render, sheet, sheets) and one BRDF's (eval, sample).
#include "renderer/cli/command.h"

namespace glossy::cli {

void addSceneOptions(CLI::App* app, SceneOptions& o) {
  app->add_option("--scene", o.scene, "glTF scene (.gltf or .glb); default: scenes/preview.gltf");
  app->add_option("--camera", o.camera, "Camera by name, or auto: frame the bound object from the preview scene's angle (default: the scene's first; auto when it has none)");
  auto* file = app->add_option("--env", o.env, "Lat-long environment map (.exr, .hdr); default: the built-in sky");
  auto* constant = app->add_option("--env-constant", o.envConstant, "Constant environment radiance: V or R,G,B");
  file->excludes(constant);
  addOption(app, options::kEnvRotate, o.envRotate);
}

void addBrdfOptions(CLI::App* app, BrdfOptions& o) {
  auto* materialOpt = app->add_option("--material", o.material, "Material parameter file (TOML)");
  auto* fitOpt = app->add_option("--fit", o.fit, "Which fit of the material: MODEL:METRIC, e.g. microfacet:E2");
  auto* measuredOpt = app->add_option("--measured", o.measured, "Measured data instead: a MERL .binary (or .binary.xz) table or a .nbrdf network");
  app->add_option("--merl-dir", o.merlDir, "Folder with MERL tables for --measured (else $GLOSSY_MERL_DIR)");
  app->add_option("--smooth-fresnel", o.smoothFresnel, "Override a smooth fit's Fresnel angle: projected (the fits' convention) or vh")
      ->check(CLI::IsMember({"projected", "vh"}));
  materialOpt->needs(fitOpt);
  fitOpt->needs(materialOpt);
  measuredOpt->excludes(materialOpt)->excludes(fitOpt);
  app->callback([app, materialOpt, measuredOpt] {
    if (measuredOpt->count() == 0 && materialOpt->count() == 0)
      throw CLI::RequiredError(app->get_name() + ": give --material F --fit MODEL:METRIC, or --measured F.binary");
  });
}

}  // namespace glossy::cli
