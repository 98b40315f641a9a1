// glossy render: one image of a glTF scene under an environment, as shared/spec/interfaces.md states.
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"
#include "renderer/app/destination.h"
#include "renderer/app/image_memory.h"
#include "renderer/app/render_job.h"
#include "renderer/cli/command.h"

#include <iostream>
#include <memory>

namespace glossy::cli {

namespace {

struct RenderOptions {
  RenderJob job;
  std::string output = "out/render.exr";
  bool half = false;
};

int runRender(const RenderOptions& o) {
  checkOutputFile(o.output, "-o", {".exr"}, Folder::Create);
  checkImageMemory(o.job.settings.width, o.job.settings.height, 1, kRenderBytesPerPixel);
  // Held until the EXR is in place: another run to the same -o is refused, not raced.
  const OutputLock lock(o.output, "-o");
  const RenderedImage r = renderImage(o.job);
  const std::filesystem::path out = o.output;
  if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
  writeExr(out, r.image, r.metadata, o.half ? PixelType::Half : PixelType::Float);
  flushNotes();  // what writing it noted (values clipped by --half) before the summary
  const RenderSettings& s = o.job.settings;
  std::cerr << "glossy: wrote " << out.string() << " (" << s.width << "x" << s.height << ", " << s.spp << " spp, "
            << r.stats.seconds << " s";
  if (r.stats.droppedSamples) std::cerr << ", " << r.stats.droppedSamples << " non-finite samples dropped";
  std::cerr << ")\n";
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& parent) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* app = parent.add_subcommand("render",
      "Render a glTF scene under an environment into a linear EXR. With no options: the material-preview "
      "scene with its bound material under the built-in sky.");
  addSceneOptions(app, o->job.scene);
  auto* material = app->add_option("--material", o->job.material, "Material file for every non-emissive mesh");
  auto* fit = app->add_option("--fit", o->job.fit, "Fit of --material: MODEL:METRIC");
  auto* measured = app->add_option("--measured", o->job.measured, "Measured data (MERL table or .nbrdf network) for every non-emissive mesh instead");
  app->add_option("--merl-dir", o->job.merlDir, "Folder with MERL tables");
  for (const OptionField& f : renderOptionFields(o->job.settings)) addOption(app, f);
  app->add_flag("--half", o->half, "Write half-float EXR (default: float); values above 65504 are clipped to it, and counted on stderr");
  app->add_option("--brdf-sampling", o->job.brdfSampling,
                  "lobe: each model samples its own lobe (default); cosine: the cosine lobe, to see what lobe sampling is worth")
      ->check(CLI::IsMember({"lobe", "cosine"}))->capture_default_str();
  app->add_flag("--reference", o->job.settings.reference,
                "Render with the reference path tracer (plain one-path code): the same image in expectation, noisier and slower");
  app->add_option("-o,--output", o->output, "Output EXR")->capture_default_str();
  material->needs(fit);
  fit->needs(material);
  measured->excludes(material)->excludes(fit);
  return {app, [o] { return runRender(*o); }};
}

}  // namespace glossy::cli
