#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"
#include "materials/fitting/metric.h"
#include "renderer/camera/camera_rays.h"
#include "renderer/image/colour_maps.h"
#include "renderer/image/flip.h"
#include "renderer/integrator/light_count.h"
#include "renderer/scene/material_binding.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace glossy {

namespace {

// Above this share of noise in the plain figure's square, the intervals were seen to cover less than they
// say: where the noise swamps the error, a seed that misses the rare bright paths underestimates both the
// error and its spread (tests/sweep/sheet_coverage_sweep_test.cpp, docs/sheets.md).
constexpr double kNoiseDominates = 0.8;
// From this many spp the intervals held whatever the noise's share (the coverage sweep's lowest count).
constexpr int kTrustedSpp = 64;

// The largest share of noise in a model's plain figure's square: 1 − r*² / noisy².
double noiseShare(const std::vector<PanelFigures>& figures) {
  double share = 0.0;
  for (const PanelFigures& f : figures)
    if (f.available && f.noisyRelativeRmse > 0.0) share = std::max(share, 1.0 - std::pow(f.relativeRmse / f.noisyRelativeRmse, 2.0));
  return share;
}

// The replicates' sample counts, pass after pass: fixed (one pass), equal time (1, 2, 4, … per replicate
// until the next would overrun the budget) or a target error (as many as the intervals' widths say).
class PassPlan {
 public:
  PassPlan(const SheetSettings& s, int panelsRendered)
      : s_(s), replicates_(s.secondsPerPanel > 0.0 || s.targetError > 0.0 ? kReplicates : std::clamp(s.spp, 1, kReplicates)),
        budget_(s.secondsPerPanel * panelsRendered) {}
  int replicates() const { return replicates_; }

  // Samples per replicate of the next pass, given those done and the figures so far (their widest interval,
  // and whether noise dominates them); 0: stop.
  int next(int done, double seconds, double lastPassSeconds, double widest, bool noisy) {
    const int cap = (s_.spp + replicates_ - 1) / replicates_;
    if (s_.targetError > 0.0) {
      if (done == 0) return std::min(cap, 4);
      // No interval to refine (no measured panel, or it is black over the object): nothing to aim at.
      if (!std::isfinite(widest) || (widest <= s_.targetError && !noisy) || done >= cap) return 0;
      // Half-widths shrink as 1/√samples: aim a little past the estimate, at most quadrupling; while noise
      // dominates, a narrow interval is not yet to be trusted: double, but no further than the spp from
      // which it is.
      const double ratio = widest / s_.targetError;
      double wanted = std::ceil(1.1 * done * ratio * ratio);
      if (noisy) wanted = std::max(wanted, std::min(std::ceil(2.2 * done), std::ceil(double(kTrustedSpp) / replicates_)));
      wanted = std::min(4.0 * done, wanted);
      int n = std::clamp(int(wanted) - done, 1, cap - done);
      if (budget_ > 0.0) {
        const double perSample = lastPassSeconds / std::max(1, lastPass_);
        n = std::min(n, int((budget_ - seconds) / std::max(perSample, 1e-9)));
      }
      lastPass_ = n;
      return std::max(n, 0);
    }
    if (budget_ > 0.0) {
      if (done == 0) return lastPass_ = std::min(1, cap);
      if (done >= cap || seconds + 2.0 * lastPassSeconds > budget_) return 0;
      return lastPass_ = std::min(done, cap - done);  // doubling, up to the --spp cap
    }
    return done == 0 ? cap : 0;
  }

 private:
  const SheetSettings& s_;
  int replicates_;
  double budget_;
  int lastPass_ = 0;  // samples per replicate of the last pass
};

// The text shortened (from the end) until it fits `width` pixels at that size: labels never run into the
// next panel.
std::string fitted(std::string text, int width, int fontSize, const std::string& font) {
  while (text.size() > 1) {
    const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, fontSize, font);
    if (!r.defined() || r.width() <= width) break;
    text.pop_back();
    while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80) text.pop_back();  // whole UTF-8 characters
  }
  return text;
}

// The measured panel's database, from its note "LABEL FILE", short enough for the panel: a network's label
// ("RGL-EPFL (NBRDF reconstruction)" → "RGL-EPFL (NBRDF reconstr.)"), else "MERL".
std::string databaseCaption(const std::string& note) {
  const std::string reconstruction = "(NBRDF reconstruction)";
  const size_t at = note.find(reconstruction);
  return at == std::string::npos ? "MERL" : note.substr(0, at) + "(NBRDF reconstr.)";
}

// A fit's parameters as its file has them, on one line: "kd = [0.1, 0.2, 0.3]; ks = [...]; n = 6679.5".
std::string paramsText(const Fit& fit) {
  MaterialFile one;
  one.name = "fit";
  one.fits = {fit};
  std::istringstream toml(toToml(one));
  std::string line, text;
  bool inFit = false;
  while (std::getline(toml, line)) {
    if (line == "[[fit]]") inFit = true;
    if (!inFit || line.empty() || line[0] == '[' || line[0] == '#' || line.starts_with("model =") || line.starts_with("metric =")) continue;
    text.append(text.empty() ? "" : "; ").append(line);
  }
  return text;
}

}  // namespace

std::vector<std::string> figureWarnings(const std::vector<PanelFigures>& figures) {
  std::vector<std::string> warnings;
  if (const double share = noiseShare(figures); share > kNoiseDominates)
    warnings.push_back(formatted("noise is up to %.0f %% of the noisy figure's square: the intervals may be too narrow; render more samples",
                                 100.0 * share));
  return warnings;
}

Verdict verdictUnderWarnings(Verdict verdict, const std::vector<std::string>& warnings) {
  // A tie claims no model; one model named closest rests on intervals a warning says may be too narrow.
  if (warnings.empty() || verdict.models.size() != 1) return verdict;
  return {{}, "no verdict: the intervals may be too narrow (warning: " + warnings.front() + ")"};
}

uint32_t noiseFloorSeed(uint32_t seed) {
  // A fixed odd multiplier and offset: a bijection, so distinct sheets' seeds give distinct floors' seeds,
  // and none is its own.
  return seed * 0x9E3779B1u + 0x7F4A7C15u;
}

const PanelRender* Sheet::measured() const {
  for (const PanelRender& p : panels)
    if (p.panel.fit.empty()) return &p;
  return nullptr;
}

SheetScene makeSheetScene(const SceneDescription& description, const EmbreeScene& bvh,
                          const Environment& environment, const Camera& camera) {
  SheetScene s{&description, &bvh, &environment, &camera, bindMaterials(description, std::nullopt).brdfs, {}, {}};
  bool anyBound = false;
  for (const SceneMaterial& m : description.materials) anyBound = anyBound || !m.glossyMaterial.empty();
  for (const SceneMaterial& m : description.materials)
    s.isObject.push_back(!m.isEmissive() && (anyBound ? !m.glossyMaterial.empty() : true));
  for (const Mesh& mesh : description.meshes) s.objectMeshes.push_back(mesh.material < 0 || s.isObject[size_t(mesh.material)]);
  return s;
}

RenderScene SheetScene::withObject(const Brdf& brdf) const {
  std::vector<Brdf> brdfs = baseBrdfs;
  for (size_t m = 0; m < brdfs.size(); ++m)
    if (isObject[m]) brdfs[m] = brdf;
  // A mesh without a material renders with the default BRDF: the object's too.
  return {description, bvh, std::move(brdfs), brdf, environment, objectMeshes};
}

Sheet renderSheet(const SheetScene& scene, const MaterialFile& material, std::shared_ptr<const MerlTable> measured,
                  const std::string& measuredNote, const SheetSettings& settings) {
  Sheet sheet;
  sheet.material = material.name;
  sheet.seed = settings.seed;
  const int w = settings.width, h = settings.height;

  sheet.objectMask.resize(size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Hit hit;
      const bool seen = scene.bvh->intersect(cameraRay(*scene.camera, w, h, Vec2(x + 0.5, y + 0.5)), hit);
      sheet.objectMask[size_t(y) * w + x] = seen && scene.objectMeshes[hit.mesh];
    }

  // The BRDF-space errors beside the image-space ones: the same E1/E2 as `glossy error`.
  std::optional<MetricData> e1, e2;
  if (measured) e1.emplace(*measured, Metric::E1), e2.emplace(*measured, Metric::E2);

  // Each panel with a BRDF becomes a scene that differs from the others only on the object.
  std::vector<RenderScene> scenes;
  std::vector<size_t> rendered;  // the panel of each scene
  std::vector<Brdf> brdfs;       // its object's
  for (const SheetPanel& panel : settings.panels) {
    PanelRender r;
    r.panel = panel;
    std::optional<Brdf> brdf;
    if (panel.fit.empty()) {
      if (measured) brdf = Measured(measured);
      r.note = measuredNote;
    } else if (const Fit* fit = material.find(FitId::parse(panel.fit, material.path.string()))) {
      // A file with only glossy's fit of a grid slot shows it there, labelled as glossy's.
      if (fit->id.str() != panel.fit) r.panel.label = SheetPanel::ofFit(fit->id).label, r.panel.fit = fit->id.str();
      brdf = makeBrdf(*fit);
      if (measured) r.brdfE1 = e1->error(*brdf), r.brdfE2 = e2->error(*brdf);
      r.params = paramsText(*fit);
    } else {
      r.note = "no " + panel.fit + " fit in " + material.name;
    }
    r.image = RgbImage(w, h);
    if (brdf) {
      r.empty = false;
      brdfs.push_back(*brdf);
      scenes.push_back(scene.withObject(*brdf));
      rendered.push_back(sheet.panels.size());
    }
    sheet.panels.push_back(std::move(r));
  }

  // Where the run chooses the spp, the object's vertices take the BSDF samples that reach a given noise
  // soonest; at a fixed spp the settings' (one unless the caller asks), so that a sheet takes the time that
  // spp always took.
  sheet.bsdfSamples = settings.targetError > 0.0 || settings.secondsPerPanel > 0.0 ? sheetBsdfSamples(brdfs) : settings.bsdfSamples;
  // The passes: each renders every replicate, each replicate its own pattern (a pass's first sample index,
  // unique per replicate and pass, seeds it), all panels of a replicate together.
  PassPlan plan(settings, int(scenes.size()));
  sheet.replicates = plan.replicates();
  for (size_t k : rendered) sheet.panels[k].replicates.assign(size_t(sheet.replicates), RgbImage(w, h));
  const auto start = std::chrono::steady_clock::now();
  int done = 0;  // samples per replicate so far
  uint64_t objectPaths = 0;
  double lastPass = 0.0, widest = std::numeric_limits<double>::infinity();
  Comparison figures;
  // Noise dominates below 64 spp (where the intervals were shown to hold): a model that matches the measured
  // panel keeps a noise share near 1 at any spp, which must not keep the passes going for ever.
  const auto noisy = [&] { return sheet.replicates * done < kTrustedSpp && noiseShare(figures.panels) > kNoiseDominates; };
  const auto compare = [&] {
    std::vector<std::vector<RgbImage>> analytic;
    const PanelRender* m = sheet.measured();
    for (const PanelRender& p : sheet.panels)
      if (!p.panel.fit.empty()) analytic.push_back(p.replicates);
    figures = m && !m->empty ? compareToMeasured(analytic, m->replicates, sheet.objectMask) : Comparison{};
    widest = figures.widestHalfWidth();
  };
  // The scene of the measured panel, rendered once more for the noise-floor row.
  const auto measuredScene = std::find_if(rendered.begin(), rendered.end(), [&](size_t k) { return sheet.panels[k].panel.fit.empty(); });
  if (settings.control && settings.secondsPerPanel <= 0.0 && settings.targetError <= 0.0 && !scenes.empty())
    settings.control->total = uint64_t(sheet.replicates) * renderTiles(w, h) * (measuredScene != rendered.end() ? 2 : 1);
  for (int n; !scenes.empty() && (n = plan.next(done, sheet.seconds, lastPass, widest, noisy())) > 0;) {
    const auto passStart = std::chrono::steady_clock::now();
    for (int j = 0; j < sheet.replicates; ++j) {
      RenderSettings r = settings;
      r.spp = n, r.firstSample = sheet.replicates * done + j * n, r.bsdfSamples = sheet.bsdfSamples;
      r.progress = settings.progress && settings.secondsPerPanel <= 0.0 && settings.targetError <= 0.0;
      RenderStats stats;
      const std::vector<RgbImage> images = renderPanels(scenes, *scene.camera, r, stats);
      if (settings.control && settings.control->cancelRequested()) throw Cancelled();
      sheet.droppedSamples += stats.droppedSamples;
      objectPaths += stats.objectPaths;
      const double wOld = double(done) / (done + n), wNew = double(n) / (done + n);
      for (size_t k = 0; k < rendered.size(); ++k) {
        std::vector<float>& acc = sheet.panels[rendered[k]].replicates[size_t(j)].pixels;
        for (size_t i = 0; i < acc.size(); ++i) acc[i] = float(wOld * acc[i] + wNew * images[k].pixels[i]);
      }
    }
    done += n;
    ++sheet.passes;
    sheet.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    lastPass = std::chrono::duration<double>(std::chrono::steady_clock::now() - passStart).count();
    if (settings.targetError > 0.0) {
      compare();
      if (settings.passLines)
        std::fprintf(stderr, "glossy: %s: pass %d: %d spp, widest interval ±%.4g (target ±%.4g), %.1f s\n", material.name.c_str(),
                     sheet.passes, sheet.replicates * done, widest, settings.targetError, sheet.seconds);
    } else if (settings.passLines && settings.secondsPerPanel > 0.0) {
      std::fprintf(stderr, "glossy: %s: pass %d: %d spp, %.1f s\n", material.name.c_str(), sheet.passes, sheet.replicates * done,
                   sheet.seconds);
    }
  }
  if (settings.targetError <= 0.0 || sheet.passes == 0) compare();
  sheet.widestHalfWidth = widest;
  sheet.spp = sheet.replicates * done;
  sheet.objectShare = sheet.spp > 0 ? double(objectPaths) / (double(sheet.spp) * w * h) : 0.0;
  sheet.warnings = figureWarnings(figures.panels);
  sheet.verdict = verdictUnderWarnings(figures.verdict, sheet.warnings);

  // The noise-floor row: the measured panel again, from another seed, with the samples of each replicate,
  // over the object's pixels, where its figures look. Off the object it keeps the measured panel's pixels,
  // as every panel does (a path that never meets the object is the same in all), so that ꟻLIP's filters
  // see at the object's edge what they see in a model's panel.
  if (measuredScene != rendered.end() && done > 0) {
    PanelRender& floor = sheet.noiseFloor;
    floor.panel = sheet.panels[*measuredScene].panel;
    floor.panel.label = "noise floor";
    floor.note = "the measured panel against an independent render of itself";
    floor.empty = false;
    floor.brdfE1 = floor.brdfE2 = 0.0;  // the measured BRDF against itself
    floor.image = RgbImage(w, h);
    const std::vector<RenderScene> alone = {scenes[size_t(measuredScene - rendered.begin())]};
    for (int j = 0; j < sheet.replicates; ++j) {
      RenderSettings r = settings;
      r.seed = noiseFloorSeed(settings.seed), r.spp = done, r.firstSample = j * done, r.progress = false;
      r.bsdfSamples = sheet.bsdfSamples;
      r.pixels = &sheet.objectMask;
      RenderStats stats;
      floor.replicates.push_back(std::move(renderPanels(alone, *scene.camera, r, stats).front()));
      const RgbImage& measured = sheet.panels[*measuredScene].replicates[size_t(j)];
      for (size_t i = 0; i < sheet.objectMask.size(); ++i)
        if (!sheet.objectMask[i]) std::copy_n(&measured.pixels[3 * i], 3, &floor.replicates.back().pixels[3 * i]);
      if (settings.control && settings.control->cancelRequested()) throw Cancelled();
    }
    const Comparison self = compareToMeasured({floor.replicates}, sheet.panels[*measuredScene].replicates, sheet.objectMask);
    floor.figures = self.panels.front();
  }
  sheet.skippedPixels = figures.skippedPixels;

  // Panel images; the figures go to the analytic panels in order, the verdict's indices to the grid's.
  size_t analytic = 0;
  std::vector<size_t> analyticPanel;
  for (size_t k = 0; k < sheet.panels.size(); ++k) {
    PanelRender& p = sheet.panels[k];
    if (!p.replicates.empty())
      for (size_t i = 0; i < p.image.pixels.size(); ++i) {
        double sum = 0.0;
        for (const RgbImage& r : p.replicates) sum += r.pixels[i];
        p.image.pixels[i] = float(sum / double(p.replicates.size()));
      }
    if (p.panel.fit.empty()) continue;
    if (analytic < figures.panels.size()) p.figures = figures.panels[analytic];
    analyticPanel.push_back(k);
    ++analytic;
  }
  for (size_t& model : sheet.verdict.models) model = analyticPanel[model];
  if (const PanelRender* m = sheet.measured(); m && !m->empty) {
    tbb::parallel_for(size_t(0), analyticPanel.size(), [&](size_t i) {
      PanelRender& p = sheet.panels[analyticPanel[i]];
      if (!p.empty && p.figures.compared) p.maps = errorMaps(p.replicates, m->replicates, sheet.objectMask);
    });
    if (std::any_of(sheet.panels.begin(), sheet.panels.end(), [](const PanelRender& p) { return p.maps.available; }))
      sheet.flipNoiseFloor = flipNoiseFloor(m->replicates, sheet.objectMask);
    if (!sheet.noiseFloor.empty && sheet.noiseFloor.figures.compared)
      sheet.noiseFloor.maps = errorMaps(sheet.noiseFloor.replicates, m->replicates, sheet.objectMask);
  }

  for (size_t i = 0; i < sheet.noiseFloor.image.pixels.size(); ++i) {
    double sum = 0.0;
    for (const RgbImage& r : sheet.noiseFloor.replicates) sum += r.pixels[i];
    sheet.noiseFloor.image.pixels[i] = float(sum / double(sheet.noiseFloor.replicates.size()));
  }

  sheet.grid = RgbImage(w * int(sheet.panels.size()), h);
  for (size_t k = 0; k < sheet.panels.size(); ++k)
    for (int y = 0; y < h; ++y)
      std::copy_n(sheet.panels[k].image.at(0, y), 3 * w, sheet.grid.at(int(k) * w, y));
  return sheet;
}

void writeSheetExr(const Sheet& sheet, const std::filesystem::path& path, std::vector<ImageAttribute> metadata, PixelType type) {
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  std::vector<ExrLayer> layers = {{"", &sheet.grid}};
  std::vector<RgbImage> maps;  // each analytic panel's two maps, as one-channel images
  maps.reserve(2 * sheet.panels.size());
  std::string names;
  for (size_t k = 0; k < sheet.panels.size(); ++k) {
    const PanelRender& p = sheet.panels[k];
    layers.push_back({p.panel.layer, &p.image, int(k) * w});
    names += (names.empty() ? "" : ",") + p.panel.layer;
    if (p.maps.available)
      for (const auto& [suffix, values] : {std::pair{"_reldiff", &p.maps.relativeDifference}, std::pair{"_flip", &p.maps.flipMap}}) {
        RgbImage& map = maps.emplace_back(w, h);
        for (size_t i = 0; i < values->size(); ++i) map.pixels[3 * i] = (*values)[i];
        layers.push_back({p.panel.layer + suffix, &map, int(k) * w, true});
      }
    const std::string key = "glossy:panel." + p.panel.layer;
    metadata.push_back({key + ".box", std::to_string(int(k) * w) + " 0 " + std::to_string(w) + " " + std::to_string(h)});
    metadata.push_back({key + ".label", p.panel.label});
    metadata.push_back({key + ".colour", p.panel.colour});
    metadata.push_back({key + ".fit", p.panel.fit.empty() ? std::string("measured") : p.panel.fit});
    metadata.push_back({key + ".empty", int(p.empty)});
    if (!p.note.empty()) metadata.push_back({key + ".note", p.note});
    if (!p.empty) metadata.push_back({key + ".spp", sheet.spp});
    const PanelFigures& f = p.figures;
    const std::string error = "glossy:error." + p.panel.layer;
    if (f.compared) {
      metadata.push_back({error + ".relativeRmseNoisy", float(f.noisyRelativeRmse)});
      metadata.push_back({error + ".luminanceRatio", float(f.luminanceRatio)});
    }
    if (f.available) {
      metadata.push_back({error + ".relativeRmse", float(f.relativeRmse)});
      metadata.push_back({error + ".noiseFree", f.clamped ? std::string("clamped at 0: the estimate of the squared error was negative")
                                                          : std::string("yes")});
    }
    if (f.hasCi) {
      metadata.push_back({error + ".relativeRmseCi", formatted("%.6g %.6g", f.relativeRmseCi.lo, f.relativeRmseCi.hi)});
      metadata.push_back({error + ".luminanceRatioCi", formatted("%.6g %.6g", f.luminanceRatioCi.lo, f.luminanceRatioCi.hi)});
    }
    if (p.brdfE1 >= 0.0) {
      metadata.push_back({error + ".E1", float(p.brdfE1)});
      metadata.push_back({error + ".E2", float(p.brdfE2)});
    }
    if (p.maps.available) {
      metadata.push_back({error + ".flip", float(p.maps.flip)});
      if (p.maps.hasFlipCi) metadata.push_back({error + ".flipCi", formatted("%.6g %.6g", p.maps.flipCi.lo, p.maps.flipCi.hi)});
    }
    if (!p.params.empty()) metadata.push_back({key + ".params", p.params});
  }
  metadata.push_back({"glossy:panels", names});
  metadata.push_back({"glossy:panelSize", std::to_string(w) + "x" + std::to_string(h)});
  metadata.push_back({"glossy:errors",
                       sheet.hasMeasured()
                           ? std::string("against the measured panel, over the object's pixels: relativeRmse with the render noise taken out "
                                         "(cross-products of independent replicates), relativeRmseNoisy without, luminanceRatio; *Ci: 95 % "
                                         "intervals; E1, E2: the fit against the measured table on the grid ") + MetricGrid::describe()
                           : std::string("none: no measured panel")});
  metadata.push_back({"glossy:errorMaps",
                       formatted("<panel>_reldiff.Y: (Y_panel - Y_measured) / max(Y_measured, 0.01 mean Y_measured) over the "
                                 "object's pixels, 0 elsewhere (Y: Rec. 709 luminance); the PNG's second row shows it clamped "
                                 "to +/-%g. <panel>_flip.Y: HDR-FLIP (Andersson et al. 2021) of the panel against the measured "
                                 "panel, %g pixels per degree; flip: its mean over the object's pixels (render noise included: it "
                                 "raises the figure), flipCi: the render noise's 95 %% spread of it (jackknife over the "
                                 "replicates); glossy:flipNoiseFloor: the same figure between two halves of the measured "
                                 "panel's samples, what noise alone shows",
                                 kRelativeDifferenceRange, FlipSettings{}.pixelsPerDegree)});
  if (sheet.flipNoiseFloor >= 0.0) metadata.push_back({"glossy:flipNoiseFloor", float(sheet.flipNoiseFloor)});
  // The noise-floor row, keyed like a panel's figures.
  if (const PanelRender& floor = sheet.noiseFloor; !floor.empty && floor.figures.compared) {
    const PanelFigures& f = floor.figures;
    metadata.push_back({"glossy:noiseFloor.seed", formatted("%u", noiseFloorSeed(sheet.seed))});
    metadata.push_back({"glossy:noiseFloor.relativeRmseNoisy", float(f.noisyRelativeRmse)});
    metadata.push_back({"glossy:noiseFloor.luminanceRatio", float(f.luminanceRatio)});
    if (f.available) metadata.push_back({"glossy:noiseFloor.relativeRmse", float(f.relativeRmse)});
    if (f.hasCi) {
      metadata.push_back({"glossy:noiseFloor.relativeRmseCi", formatted("%.6g %.6g", f.relativeRmseCi.lo, f.relativeRmseCi.hi)});
      metadata.push_back({"glossy:noiseFloor.luminanceRatioCi", formatted("%.6g %.6g", f.luminanceRatioCi.lo, f.luminanceRatioCi.hi)});
    }
    if (floor.maps.available) {
      metadata.push_back({"glossy:noiseFloor.flip", float(floor.maps.flip)});
      if (floor.maps.hasFlipCi)
        metadata.push_back({"glossy:noiseFloor.flipCi", formatted("%.6g %.6g", floor.maps.flipCi.lo, floor.maps.flipCi.hi)});
    }
  }
  if (!sheet.warnings.empty()) {
    std::string text;
    for (const std::string& w : sheet.warnings) text.append(text.empty() ? "" : "\n").append(w);
    metadata.push_back({"glossy:warnings", text});
  }
  metadata.push_back({"glossy:verdict", verdictText(sheet)});
  metadata.push_back({"glossy:replicates", sheet.replicates});
  metadata.push_back({"glossy:passes", sheet.passes});
  metadata.push_back({"glossy:bsdfSamples", sheet.bsdfSamples});
  metadata.push_back({"glossy:objectShare", float(sheet.objectShare)});
  writeLayeredExr(path, layers, metadata, type);
}

namespace {

int labelFontSize(int panelWidth) { return std::clamp(panelWidth / 13, 9, 16); }
int labelStrip(int panelWidth) { return 4 * labelFontSize(panelWidth) + labelFontSize(panelWidth) / 2 + 10; }
int smallFontSize(int panelWidth) { return std::max(8, labelFontSize(panelWidth) - 2); }
// Under the error maps: the noise floor's line and the warnings' line.
int noteStrip(int panelWidth) { return 2 * (smallFontSize(panelWidth) + 4) + 6; }

}  // namespace

SheetPngSize sheetPngSize(int panelWidth, int panelHeight, int panels) {
  const int plain = panelHeight + labelStrip(panelWidth);
  return {panelWidth * panels, plain, plain + panelHeight + noteStrip(panelWidth)};
}

void writeSheetPng(const Sheet& sheet, const std::filesystem::path& path, double exposure, const std::string& fontPath) {
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  const int n = int(sheet.panels.size());
  const int fontSize = labelFontSize(w);
  const int small = smallFontSize(w);
  const int strip = labelStrip(w);
  const bool mapRow = sheet.hasMeasured();
  const SheetPngSize size = sheetPngSize(w, h, n);
  const int height = mapRow ? size.heightWithMaps : size.height;
  OIIO::ImageBuf buf(OIIO::ImageSpec(size.width, height, 3, OIIO::TypeDesc::FLOAT));
  const float stripColour[3] = {0.12f, 0.12f, 0.12f}, emptyColour[3] = {0.25f, 0.25f, 0.25f};
  OIIO::ImageBufAlgo::fill(buf, stripColour);
  const double scale = std::exp2(exposure);
  for (int k = 0; k < n; ++k) {
    const PanelRender& p = sheet.panels[size_t(k)];
    if (p.empty) {
      OIIO::ImageBufAlgo::fill(buf, emptyColour, OIIO::ROI(k * w, (k + 1) * w, 0, h));
      continue;
    }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float* px = p.image.at(x, y);
        const float v[3] = {srgbEncode(px[0] * scale), srgbEncode(px[1] * scale), srgbEncode(px[2] * scale)};
        buf.setpixel(k * w + x, y, v, 3);
      }
  }
  const float white[3] = {0.95f, 0.95f, 0.95f}, grey[3] = {0.7f, 0.7f, 0.7f};
  const auto text = [&](const std::string& line, int x, int y, int size, OIIO::cspan<float> colour, int width) {
    OIIO::ImageBufAlgo::render_text(buf, x, y, fitted(line, width, size, fontPath), size, fontPath, colour);
  };
  for (int k = 0; k < n; ++k) {
    const PanelRender& p = sheet.panels[size_t(k)];
    auto label = [&](const std::string& line, int y, int size, OIIO::cspan<float> colour) { text(line, k * w + 3, h + y, size, colour, w - 6); };
    std::string second;
    if (p.empty)
      second = p.panel.fit.empty() ? "no MERL data (--merl-dir)" : "no fit";
    else if (p.figures.hasCi)
      // Narrow panels get the figures without their names. ASCII only: OpenImageIO's text drops the high
      // bit of every byte, so "±" would come out as "1".
      second = formatted(w >= 200 ? "rRMSE %.3f +/-%.3f  lum x%.2f" : "%.3f+/-%.3f x%.2f", p.figures.relativeRmse,
                         p.figures.relativeRmseCi.halfWidth(), p.figures.luminanceRatio);
    else if (p.figures.compared)
      second = formatted(w >= 120 ? "rRMSE %.3f (noisy)  lum x%.2f" : "%.3f? x%.2f",
                         p.figures.available ? p.figures.relativeRmse : p.figures.noisyRelativeRmse, p.figures.luminanceRatio);
    else if (!p.panel.fit.empty())
      second = "no measured panel";
    else
      second = databaseCaption(p.note);
    label(p.panel.label, fontSize + 2, fontSize, white);
    if (!second.empty()) label(second, 2 * fontSize + 5, small, grey);
    if (p.brdfE1 >= 0.0) label(formatted(w >= 120 ? "E1 %.3g  E2 %.3g" : "%.2g %.2g", p.brdfE1, p.brdfE2), 3 * fontSize + 7, small, grey);
    if (p.maps.available)
      label(p.maps.hasFlipCi ? formatted(w >= 120 ? "FLIP %.3f +/-%.3f" : "F %.3f+/-%.3f", p.maps.flip, p.maps.flipCi.halfWidth())
                             : formatted("FLIP %.3f", p.maps.flip),
            4 * fontSize + 9, small, grey);
  }

  // The second row: where each model is brighter (red) or darker (blue) than the measured panel.
  if (mapRow) {
    const int top = h + strip;
    const float background[3] = {0.2f, 0.2f, 0.2f};
    for (int k = 0; k < n; ++k) {
      const PanelRender& p = sheet.panels[size_t(k)];
      const OIIO::ROI box(k * w, (k + 1) * w, top, top + h);
      if (p.panel.fit.empty()) {
        // The legend, under the measured panel: a colour bar over the map's range and what it shows (not in
        // thumbnails, where it would not be legible).
        OIIO::ImageBufAlgo::fill(buf, stripColour, box);
        if (w < 96 || h < 64) continue;
        const int barLeft = k * w + w / 10, barWidth = w - w / 5, barTop = top + h / 2 - fontSize, barHeight = std::max(6, h / 12);
        for (int x = 0; x < barWidth; ++x) {
          const DisplayColour c = divergingColour(2.0 * (x + 0.5) / barWidth - 1.0);
          for (int y = 0; y < barHeight; ++y) buf.setpixel(barLeft + x, barTop + y, c.data(), 3);
        }
        const std::string range = formatted("%.0f%%", 100.0 * kRelativeDifferenceRange);
        text("-" + range, barLeft - 2, barTop + barHeight + small + 2, small, grey, w / 3);
        text("0", barLeft + barWidth / 2 - small / 4, barTop + barHeight + small + 2, small, grey, w / 3);
        text("+" + range, barLeft + barWidth - 3 * small, barTop + barHeight + small + 2, small, grey, w / 3);
        text("luminance vs measured:", k * w + 3, top + fontSize + 2, small, white, w - 6);
        text("(model - meas.) / meas.", k * w + 3, top + 2 * fontSize + 4, small, grey, w - 6);
        text("darker  <  >  brighter", k * w + 3, barTop + barHeight + 2 * small + 6, small, grey, w - 6);
        continue;
      }
      if (!p.maps.available) {
        OIIO::ImageBufAlgo::fill(buf, emptyColour, box);
        continue;
      }
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          const size_t i = size_t(y) * size_t(w) + size_t(x);
          if (!sheet.objectMask[i]) {
            buf.setpixel(k * w + x, top + y, background, 3);
            continue;
          }
          const DisplayColour c = divergingColour(p.maps.relativeDifference[i] / kRelativeDifferenceRange);
          buf.setpixel(k * w + x, top + y, c.data(), 3);
        }
    }
  }
  // The strip under the maps: what noise alone shows, and the warnings, across the whole width.
  if (mapRow) {
    const int top = h + strip + h;
    const PanelRender& floor = sheet.noiseFloor;
    std::string line = "noise floor (measured vs. an independent render of itself): ";
    if (floor.empty || !floor.figures.compared)
      line += "none";
    else {
      const PanelFigures& f = floor.figures;
      line += f.hasCi ? formatted("rRMSE %.3f [%.3f, %.3f]  lum x%.3f [%.3f, %.3f]", f.relativeRmse, f.relativeRmseCi.lo,
                                  f.relativeRmseCi.hi, f.luminanceRatio, f.luminanceRatioCi.lo, f.luminanceRatioCi.hi)
                      : formatted("rRMSE %.3f  lum x%.3f", f.relativeRmse, f.luminanceRatio);
      if (floor.maps.available) line += formatted("  FLIP %.3f", floor.maps.flip);
    }
    text(line, 3, top + small + 2, small, grey, size.width - 6);
    const float orange[3] = {1.0f, 0.6f, 0.2f};
    std::string warnings;
    for (const std::string& w : sheet.warnings) warnings.append(warnings.empty() ? "warning: " : "; ").append(w);
    text(warnings.empty() ? std::string("no warnings") : warnings, 3, top + 2 * small + 8, small,
         warnings.empty() ? OIIO::cspan<float>(grey) : OIIO::cspan<float>(orange), size.width - 6);
  }
  if (buf.has_error()) std::fprintf(stderr, "glossy: %s: labels not drawn: %s\n", path.string().c_str(), buf.geterror().c_str());
  std::vector<unsigned char> rgb(size_t(w * n) * size_t(height) * 3);
  if (!buf.get_pixels(buf.roi(), OIIO::TypeDesc::UINT8, rgb.data())) throw std::runtime_error(path.string() + ": " + buf.geterror());
  writeRgb8(path, w * n, height, rgb);
}

std::string verdictText(const Sheet& sheet) {
  const std::vector<size_t>& models = sheet.verdict.models;
  if (models.empty()) return sheet.verdict.why.empty() ? std::string("no verdict") : sheet.verdict.why;
  std::string names;
  for (size_t k : models) names.append(names.empty() ? "" : ", ").append(sheet.panels[k].panel.label);
  return (models.size() == 1 ? "closest: " : "tie: ") + names;
}

std::string errorTable(const Sheet& sheet) {
  std::ostringstream s;
  s << sheet.material << ": ";
  const std::string note = sheet.measured() ? sheet.measured()->note : "none in the grid";
  if (sheet.hasMeasured())
    s << "error of each model against the measured panel (" << note << "), over the object's pixels, "
      << formatted("%d spp in %d replicates", sheet.spp, sheet.replicates) << "\n";
  else
    s << "no measured panel (" << note << "), so no errors against it\n";
  // The label column fits the longest label (a glossy fit's says so: "GGX E2 (glossy fit)").
  int w = 14;
  for (const PanelRender& p : sheet.panels) w = std::max(w, int(p.panel.label.size()));
  s << formatted("  %-*s   rel. RMSE, noise-free [95 %%]   luminance ratio [95 %%]    HDR-FLIP [95 %%]            noisy rRMSE   BRDF E1   BRDF E2\n", w, "panel");
  bool clamped = false;
  const auto row = [&](const PanelRender& p) {
    const PanelFigures& f = p.figures;
    const std::string r = !f.available ? "-"
                          : f.hasCi    ? formatted("%.4f [%.4f, %.4f]%s", f.relativeRmse, f.relativeRmseCi.lo, f.relativeRmseCi.hi,
                                                   f.clamped ? "*" : "")
                                       : formatted("%.4f%s", f.relativeRmse, f.clamped ? "*" : "");
    const std::string l = f.hasCi ? formatted("%.4f [%.4f, %.4f]", f.luminanceRatio, f.luminanceRatioCi.lo, f.luminanceRatioCi.hi)
                                  : formatted("%.4f", f.luminanceRatio);
    const std::string flip = !p.maps.available ? "-"
                             : p.maps.hasFlipCi ? formatted("%.4f [%.4f, %.4f]", p.maps.flip, p.maps.flipCi.lo, p.maps.flipCi.hi)
                                                : formatted("%.4f", p.maps.flip);
    clamped = clamped || f.clamped;
    s << formatted("  %-*s   %-29s  %-24s  %-25s  %11.4f   %7.4f   %7.4f\n", w, p.panel.label.c_str(), r.c_str(), l.c_str(),
                   flip.c_str(), f.noisyRelativeRmse, p.brdfE1, p.brdfE2);
  };
  for (const PanelRender& p : sheet.panels) {
    if (p.empty) {
      s << formatted("  %-*s   %s\n", w, p.panel.label.c_str(), p.note.c_str());
      continue;
    }
    if (!p.figures.compared) {
      s << formatted("  %-*s   %s\n", w, p.panel.label.c_str(), p.panel.fit.empty() ? "(the reference)" : "-");
      continue;
    }
    row(p);
  }
  // What an exact model would score: the floor under every column's figure.
  if (!sheet.noiseFloor.empty && sheet.noiseFloor.figures.compared) row(sheet.noiseFloor);
  if (clamped) s << "  * the estimate of the squared error came out negative (the model is within the noise): shown as 0\n";
  // Say so rather than let a narrow interval pass for a precise one.
  for (const std::string& warning : sheet.warnings) s << "  warning: " << warning << "\n";
  if (sheet.skippedPixels > 0) s << "  " << sheet.skippedPixels << " object pixels left out: not finite in some panel\n";
  if (sheet.flipNoiseFloor >= 0.0)
    s << formatted("  HDR-FLIP includes render noise, which raises it; the [95 %%] is the noise's spread. Noise alone gives "
                   "%.4f (the measured panel against itself, half its samples each)\n",
                   sheet.flipNoiseFloor);
  if (sheet.hasMeasured()) {
    s << "  " << verdictText(sheet);
    if (sheet.verdict.models.size() > 1) s << " (not separated at 95 %: more samples, e.g. --target-error, may decide)";
    s << "\n";
  }
  return s.str();
}

}  // namespace glossy
