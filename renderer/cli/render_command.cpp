// glossy render: one image of a glTF scene under an environment, as shared/spec/interfaces.md states.
#include "materials/core/input_error.h"
#include "materials/core/notes.h"
#include "materials/models/registry.h"
#include "materials/params/material_file.h"
#include "renderer/cli/brdf_options.h"
#include "renderer/cli/command.h"
#include "renderer/cli/destination.h"
#include "renderer/cli/image_memory.h"
#include "renderer/cli/scene_options.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/scene/material_binding.h"

#include <iostream>
#include <memory>

namespace glossy::cli {

namespace {

struct RenderOptions {
  SceneOptions scene;
  std::string material, fit, measured, merlDir, output = "out/render.exr";
  std::string brdfSampling = "lobe";
  RenderSettings settings;
  bool half = false;
};

int runRender(RenderOptions o) {
  checkOutputFile(o.output, "-o", {".exr"}, Folder::Create);
  checkImageMemory(o.settings.width, o.settings.height, 1, kRenderBytesPerPixel);
  const std::string scenePath = o.scene.scenePath();
  const SceneDescription description = loadGltf(scenePath);

  std::optional<BrdfChoice> override;
  int measuredInvalidBins = -1;
  std::string measuredLabelText;
  if (!o.measured.empty()) {
    const std::filesystem::path path = findMeasured(o.measured, o.merlDir);
    auto table = loadMeasured(path);
    measuredInvalidBins = int(table->invalidBins());
    measuredLabelText = measuredLabel(path);
    override = BrdfChoice{Measured{std::move(table)}, path.string(), "measured"};
  } else if (!o.material.empty()) {
    override = brdfFromMaterialFile(o.material, o.fit);
  }

  MaterialBinding binding = bindMaterials(description, override);
  const Environment environment = o.scene.environment();
  const EmbreeScene bvh(description);
  const Brdf defaultBrdf = override ? override->brdf : Lambertian{Rgb(0.5)};
  const RenderScene scene{&description, &bvh, std::move(binding.brdfs), defaultBrdf, &environment};

  const Camera camera = o.scene.cameraOf(description, double(o.settings.width) / double(o.settings.height));

  o.settings.cosineBrdfSampling = o.brdfSampling == "cosine";
  flushNotes();  // the input is good: what loading it noted comes before the (long) render
  RenderStats stats;
  const RgbImage image = render(scene, camera, o.settings, stats);

  std::string materialText = override ? override->material : "";
  if (!override)
    for (const auto& b : binding.bindings) materialText += (materialText.empty() ? "" : "; ") + b;
  std::vector<ImageAttribute> metadata = {
      {"glossy:material", materialText.empty() ? std::string("scene base colours") : materialText},
      {"glossy:fit", override ? override->fit : binding.commonFit.empty() ? std::string("per scene binding") : binding.commonFit},
      {"glossy:spp", o.settings.spp},
      // EXR has no unsigned attribute: seeds beyond int's range are written as their decimal text.
      o.settings.seed <= uint32_t(INT32_MAX) ? ImageAttribute{"glossy:seed", int(o.settings.seed)}
                                             : ImageAttribute{"glossy:seed", std::to_string(o.settings.seed)},
      {"glossy:maxDepth", o.settings.maxDepth},
      {"glossy:lightSamples", o.settings.lightSamples},
      {"glossy:brdfSampling", o.brdfSampling},
      {"glossy:scene", scenePath},
      {"glossy:env", environment.description()},
      {"glossy:smoothFresnel", binding.smoothFresnel},
      {"glossy:conventions", modelConventions()},
      {"glossy:droppedSamples", int(std::min<uint64_t>(stats.droppedSamples, uint64_t(INT32_MAX)))},
      {"glossy:renderSeconds", float(stats.seconds)},
      {"glossy:version", std::string(GLOSSY_VERSION)},
  };
  if (measuredInvalidBins >= 0) {
    metadata.push_back({"glossy:measuredInvalidBins", measuredInvalidBins});
    metadata.push_back({"glossy:measured", measuredLabelText});
  }
  const std::filesystem::path out = o.output;
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeExr(out, image, metadata, o.half ? PixelType::Half : PixelType::Float);
  std::cerr << "glossy: wrote " << out.string() << " (" << o.settings.width << "x" << o.settings.height << ", "
            << o.settings.spp << " spp, " << stats.seconds << " s";
  if (stats.droppedSamples) std::cerr << ", " << stats.droppedSamples << " non-finite samples dropped";
  std::cerr << ")\n";
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& parent) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* app = parent.add_subcommand("render",
      "Render a glTF scene under an environment into a linear EXR. With no options: the material-preview "
      "scene with its bound material under the built-in sky.");
  o->scene.addTo(app);
  auto* material = app->add_option("--material", o->material, "Material file for every non-emissive mesh");
  auto* fit = app->add_option("--fit", o->fit, "Fit of --material: MODEL:METRIC");
  auto* measured = app->add_option("--measured", o->measured, "Measured data (MERL table or .nbrdf network) for every non-emissive mesh instead");
  app->add_option("--merl-dir", o->merlDir, "Folder with MERL tables");
  app->add_option("--spp", o->settings.spp, "Samples per pixel")->check(CLI::Range(1, INT32_MAX))->capture_default_str();
  app->add_option("--seed", o->settings.seed, "Random seed")->capture_default_str();
  app->add_option("--threads", o->settings.threads, "Threads (0 = all cores)")->check(integerIn(0, kMaxThreads));
  app->add_option("--width", o->settings.width, "Image width")->check(CLI::Range(1, 1 << 15))->capture_default_str();
  app->add_option("--height", o->settings.height, "Image height")->check(CLI::Range(1, 1 << 15))->capture_default_str();
  app->add_option("--max-depth", o->settings.maxDepth, "Path segments at most (1 = emitters only, 3 = one indirect bounce)")
      ->check(CLI::Range(1, 1000))->capture_default_str();
  app->add_option("--light-samples", o->settings.lightSamples,
                  "Light samples at a path's first vertex (more: less noise from the lights at less than a path's cost)")
      ->check(CLI::Range(1, kMaxLightSamples))->capture_default_str();
  app->add_flag("--half", o->half, "Write half-float EXR (default: float)");
  app->add_option("--brdf-sampling", o->brdfSampling,
                  "lobe: each model samples its own lobe (default); cosine: the cosine lobe, to see what lobe sampling is worth")
      ->check(CLI::IsMember({"lobe", "cosine"}))->capture_default_str();
  app->add_flag("--reference", o->settings.reference,
                "Trace one path at a time (the reference path tracer): the same image, more slowly");
  app->add_option("-o,--output", o->output, "Output EXR")->capture_default_str();
  material->needs(fit);
  fit->needs(material);
  measured->excludes(material)->excludes(fit);
  return {app, [o] { return runRender(*o); }};
}

}  // namespace glossy::cli
