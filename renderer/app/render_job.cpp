#include "renderer/app/render_job.h"

#include "materials/core/text.h"
#include "renderer/util/notes.h"
#include "materials/models/registry.h"
#include "renderer/app/brdf_options.h"
#include "renderer/app/option_specs.h"

namespace glossy::app {

std::vector<ImageAttribute> madeWith(const RenderSettings& s, const std::string& scene, const std::string& env, uint64_t droppedSamples,
                                     double seconds) {
  return {seedAttribute(s.seed),
          {std::string(options::kMaxDepth.attribute), s.maxDepth},
          {std::string(options::kLightSamples.attribute), s.lightSamples},
          {"glossy:scene", scene},
          {"glossy:env", env},
          {"glossy:conventions", modelConventions()},
          {"glossy:droppedSamples", int(std::min<uint64_t>(droppedSamples, INT32_MAX))},
          {"glossy:renderSeconds", float(seconds)},
          {"glossy:version", std::string(GLOSSY_VERSION)}};
}

RenderedImage renderImage(const RenderJob& job) {
  const std::string scenePath = job.scene.scenePath();
  const SceneDescription description = loadGltf(scenePath);

  std::optional<BrdfChoice> override = job.brdf;
  int measuredInvalidBins = -1;
  std::string measuredLabelText;
  if (!override && !job.measured.empty()) {
    const std::filesystem::path path = findMeasured(job.measured, job.merlDir);
    auto table = loadMeasured(path);
    measuredInvalidBins = int(table->invalidBins());
    measuredLabelText = measuredLabel(path);
    override = BrdfChoice{Measured{std::move(table)}, path.string(), "measured", std::nullopt};
  } else if (!override && !job.material.empty()) {
    override = brdfFromMaterialFile(job.material, job.fit);
  }

  MaterialBinding binding = bindMaterials(description, override);
  const Environment environment = job.scene.environment();
  const EmbreeScene bvh(description);
  const Brdf defaultBrdf = override ? override->brdf : Lambertian{Rgb(0.5)};
  const RenderScene scene{&description, &bvh, std::move(binding.brdfs), defaultBrdf, &environment};

  RenderSettings settings = job.settings;
  const Camera camera = job.scene.cameraOf(description, double(settings.width) / double(settings.height));
  settings.cosineBrdfSampling = job.brdfSampling == "cosine";
  if (settings.control) settings.control->total = renderTiles(settings.width, settings.height);
  flushNotes();  // the input is good: what loading it noted comes before the (long) render

  RenderedImage out;
  out.image = render(scene, camera, settings, out.stats);

  const std::string materialText = override ? override->material : joined(binding.bindings, "; ");
  out.metadata = madeWith(settings, scenePath, environment.description(), out.stats.droppedSamples, out.stats.seconds);
  out.metadata.insert(out.metadata.end(),
                      {{"glossy:material", materialText.empty() ? std::string("scene base colours") : materialText},
                       {"glossy:fit", override ? override->fit : binding.commonFit.empty() ? std::string("per scene binding") : binding.commonFit},
                       {std::string(options::kSpp.attribute), settings.spp},
                       {"glossy:brdfSampling", job.brdfSampling}});
  for (const auto& [key, value] : choiceAttributes(binding.fits)) out.metadata.push_back({key, value});
  if (measuredInvalidBins >= 0) {
    out.metadata.push_back({"glossy:measuredInvalidBins", measuredInvalidBins});
    out.metadata.push_back({"glossy:measured", measuredLabelText});
  }
  return out;
}

}  // namespace glossy::app
