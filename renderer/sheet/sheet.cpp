// A material's comparison sheet, rendered (renderSheet's phases: the object's pixels, the panels and their
// scenes, the passes, the noise-floor row, the images, figures and maps). Its EXR, PNG and table are
// sheet_exr.cpp's, sheet_png.cpp's and error_table.cpp's; the passes' sample counts pass_plan.h's.
#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"
#include "materials/fitting/metric.h"
#include "renderer/camera/camera_rays.h"
#include "renderer/integrator/light_count.h"
#include "renderer/scene/material_binding.h"
#include "renderer/sheet/pass_plan.h"
#include "renderer/util/notes.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <sstream>

namespace glossy {

namespace {

// Above this share of noise in the plain figure's square, the intervals were seen to cover less than they
// say: where the noise swamps the error, a seed that misses the rare bright paths underestimates both the
// error and its spread (tests/sweep/sheet_coverage_sweep_test.cpp, docs/sheets.md).
constexpr double kNoiseDominates = 0.8;

// The largest share of noise in a model's plain figure's square: 1 − r*² / noisy².
double noiseShare(const std::vector<PanelFigures>& figures) {
  double share = 0.0;
  for (const PanelFigures& f : figures)
    if (f.available && f.noisyRelativeRmse > 0.0) share = std::max(share, 1.0 - std::pow(f.relativeRmse / f.noisyRelativeRmse, 2.0));
  return share;
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

namespace {

// renderSheet's phases, in order, over what they share: where the object is; which panels have a BRDF, each
// a scene that differs from the others only on the object; the passes over them; the noise-floor row;
// the panels' images, figures and maps.
class SheetRender {
 public:
  SheetRender(const SheetScene& scene, const MaterialFile& material, std::shared_ptr<const MerlTable> measured,
              const std::string& measuredNote, const SheetSettings& settings)
      : scene_(scene), material_(material), measured_(std::move(measured)), measuredNote_(measuredNote), settings_(settings),
        w_(settings.width), h_(settings.height) {
    sheet_.material = material.name;
    sheet_.seed = settings.seed;
  }

  Sheet run() {
    findObject();
    choosePanels();
    renderPasses();
    renderNoiseFloor();
    finishPanels();
    return std::move(sheet_);
  }

 private:
  void findObject() {
    sheet_.objectMask.resize(size_t(w_) * size_t(h_));
    for (int y = 0; y < h_; ++y)
      for (int x = 0; x < w_; ++x) {
        Hit hit;
        const bool seen = scene_.bvh->intersect(cameraRay(*scene_.camera, w_, h_, Vec2(x + 0.5, y + 0.5)), hit);
        sheet_.objectMask[size_t(y) * w_ + x] = seen && scene_.objectMeshes[hit.mesh];
      }
  }

  void choosePanels() {
    // The BRDF-space errors beside the image-space ones: the same E1/E2 as `glossy error`.
    std::optional<MetricData> e1, e2;
    if (measured_) e1.emplace(*measured_, Metric::E1), e2.emplace(*measured_, Metric::E2);
    std::vector<Brdf> brdfs;  // each scene's object's
    for (const SheetPanel& panel : settings_.panels) {
      PanelRender r;
      r.panel = panel;
      std::optional<Brdf> brdf;
      if (panel.fit.empty()) {
        if (measured_) brdf = Measured(measured_);
        r.note = measuredNote_;
      } else if (const Fit* fit = material_.find(FitId::parse(panel.fit, material_.path.string()))) {
        // A file with only glossy's fit of a grid slot shows it there, labelled as glossy's.
        if (fit->id.str() != panel.fit) r.panel.label = SheetPanel::ofFit(fit->id).label, r.panel.fit = fit->id.str();
        brdf = makeBrdf(*fit);
        if (measured_) r.brdfE1 = e1->error(*brdf), r.brdfE2 = e2->error(*brdf);
        r.params = paramsText(*fit);
      } else {
        r.note = "no " + panel.fit + " fit in " + material_.name;
      }
      r.image = RgbImage(w_, h_);
      if (brdf) {
        r.empty = false;
        brdfs.push_back(*brdf);
        scenes_.push_back(scene_.withObject(*brdf));
        rendered_.push_back(sheet_.panels.size());
      }
      sheet_.panels.push_back(std::move(r));
    }
    // Where the run chooses the spp, the object's vertices take the BSDF samples that reach a given noise
    // soonest; at a fixed spp the settings' (one unless the caller asks), so that a sheet takes the time that
    // spp always took.
    sheet_.bsdfSamples = settings_.targetError > 0.0 || settings_.secondsPerPanel > 0.0 ? sheetBsdfSamples(brdfs) : settings_.bsdfSamples;
    for (size_t k = 0; k < rendered_.size() && measuredScene_ < 0; ++k)
      if (sheet_.panels[rendered_[k]].panel.fit.empty()) measuredScene_ = int(k);
  }

  // The passes: each renders every replicate, each replicate its own pattern (a pass's first sample index,
  // unique per replicate and pass, seeds it), all panels of a replicate together. Each pass's images join
  // the replicates' means.
  void renderPasses() {
    PassPlan plan(settings_, int(scenes_.size()));
    sheet_.replicates = plan.replicates();
    for (size_t k : rendered_) sheet_.panels[k].replicates.assign(size_t(sheet_.replicates), RgbImage(w_, h_));
    const auto start = std::chrono::steady_clock::now();
    uint64_t objectPaths = 0;
    double lastPass = 0.0;
    // Noise dominates below 64 spp (where the intervals were shown to hold): a model that matches the measured
    // panel keeps a noise share near 1 at any spp, which must not keep the passes going for ever.
    const auto noisy = [&] { return sheet_.replicates * done_ < kTrustedSpp && noiseShare(figures_.panels) > kNoiseDominates; };
    if (settings_.control && settings_.secondsPerPanel <= 0.0 && settings_.targetError <= 0.0 && !scenes_.empty())
      settings_.control->total = uint64_t(sheet_.replicates) * renderTiles(w_, h_) * (measuredScene_ >= 0 ? 2 : 1);
    for (int n; !scenes_.empty() && (n = plan.next(done_, sheet_.seconds, lastPass, widest_, noisy())) > 0;) {
      const auto passStart = std::chrono::steady_clock::now();
      for (int j = 0; j < sheet_.replicates; ++j) {
        RenderSettings r = settings_;
        r.spp = n, r.firstSample = sheet_.replicates * done_ + j * n, r.bsdfSamples = sheet_.bsdfSamples;
        r.progress = settings_.progress && settings_.secondsPerPanel <= 0.0 && settings_.targetError <= 0.0;
        RenderStats stats;
        const std::vector<RgbImage> images = renderPanels(scenes_, *scene_.camera, r, stats);
        if (settings_.control && settings_.control->cancelRequested()) throw Cancelled();
        sheet_.droppedSamples += stats.droppedSamples;
        objectPaths += stats.objectPaths;
        const double wOld = double(done_) / (done_ + n), wNew = double(n) / (done_ + n);
        for (size_t k = 0; k < rendered_.size(); ++k) {
          std::vector<float>& acc = sheet_.panels[rendered_[k]].replicates[size_t(j)].pixels;
          for (size_t i = 0; i < acc.size(); ++i) acc[i] = float(wOld * acc[i] + wNew * images[k].pixels[i]);
        }
      }
      done_ += n;
      ++sheet_.passes;
      sheet_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      lastPass = std::chrono::duration<double>(std::chrono::steady_clock::now() - passStart).count();
      if (settings_.targetError > 0.0) {
        compare();
        if (settings_.passLines)
          tell(formatted("glossy: %s: pass %d: %d spp, widest interval ±%.4g (target ±%.4g), %.1f s", material_.name.c_str(),
                         sheet_.passes, sheet_.replicates * done_, widest_, settings_.targetError, sheet_.seconds));
      } else if (settings_.passLines && settings_.secondsPerPanel > 0.0) {
        tell(formatted("glossy: %s: pass %d: %d spp, %.1f s", material_.name.c_str(), sheet_.passes, sheet_.replicates * done_,
                       sheet_.seconds));
      }
    }
    if (settings_.targetError <= 0.0 || sheet_.passes == 0) compare();
    sheet_.widestHalfWidth = widest_;
    sheet_.spp = sheet_.replicates * done_;
    sheet_.objectShare = sheet_.spp > 0 ? double(objectPaths) / (double(sheet_.spp) * w_ * h_) : 0.0;
    sheet_.warnings = figureWarnings(figures_.panels);
    sheet_.verdict = verdictUnderWarnings(figures_.verdict, sheet_.warnings);
    sheet_.skippedPixels = figures_.skippedPixels;
  }

  // The analytic panels' figures against the measured panel, and their widest interval.
  void compare() {
    std::vector<std::vector<RgbImage>> analytic;
    const PanelRender* m = sheet_.measured();
    for (const PanelRender& p : sheet_.panels)
      if (!p.panel.fit.empty()) analytic.push_back(p.replicates);
    figures_ = m && !m->empty ? compareToMeasured(analytic, m->replicates, sheet_.objectMask) : Comparison{};
    widest_ = figures_.widestHalfWidth();
  }

  // The noise-floor row: the measured panel again, from another seed, with the samples of each replicate,
  // over the object's pixels, where its figures look. Off the object it keeps the measured panel's pixels,
  // as every panel does (a path that never meets the object is the same in all), so that ꟻLIP's filters
  // see at the object's edge what they see in a model's panel.
  void renderNoiseFloor() {
    if (measuredScene_ < 0 || done_ == 0) return;
    const PanelRender& measured = sheet_.panels[rendered_[size_t(measuredScene_)]];
    PanelRender& floor = sheet_.noiseFloor;
    floor.panel = measured.panel;
    floor.panel.label = "noise floor";
    floor.note = "the measured panel against an independent render of itself";
    floor.empty = false;
    floor.brdfE1 = floor.brdfE2 = 0.0;  // the measured BRDF against itself
    const std::vector<RenderScene> alone = {scenes_[size_t(measuredScene_)]};
    for (int j = 0; j < sheet_.replicates; ++j) {
      RenderSettings r = settings_;
      r.seed = noiseFloorSeed(settings_.seed), r.spp = done_, r.firstSample = j * done_, r.progress = false;
      r.bsdfSamples = sheet_.bsdfSamples;
      r.pixels = &sheet_.objectMask;
      RenderStats stats;
      floor.replicates.push_back(std::move(renderPanels(alone, *scene_.camera, r, stats).front()));
      const RgbImage& m = measured.replicates[size_t(j)];
      for (size_t i = 0; i < sheet_.objectMask.size(); ++i)
        if (!sheet_.objectMask[i]) std::copy_n(&m.pixels[3 * i], 3, &floor.replicates.back().pixels[3 * i]);
      if (settings_.control && settings_.control->cancelRequested()) throw Cancelled();
    }
    floor.figures = compareToMeasured({floor.replicates}, measured.replicates, sheet_.objectMask).panels.front();
    floor.image = meanOf(floor.replicates, w_, h_);
  }

  // Panel images; the figures go to the analytic panels in order, the verdict's indices to the grid's; the
  // error maps; the grid.
  void finishPanels() {
    size_t analytic = 0;
    std::vector<size_t> analyticPanel;
    for (size_t k = 0; k < sheet_.panels.size(); ++k) {
      PanelRender& p = sheet_.panels[k];
      if (!p.replicates.empty()) p.image = meanOf(p.replicates, w_, h_);
      if (p.panel.fit.empty()) continue;
      if (analytic < figures_.panels.size()) p.figures = figures_.panels[analytic];
      analyticPanel.push_back(k);
      ++analytic;
    }
    for (size_t& model : sheet_.verdict.models) model = analyticPanel[model];
    if (const PanelRender* m = sheet_.measured(); m && !m->empty) {
      tbb::parallel_for(size_t(0), analyticPanel.size(), [&](size_t i) {
        PanelRender& p = sheet_.panels[analyticPanel[i]];
        if (!p.empty && p.figures.compared) p.maps = errorMaps(p.replicates, m->replicates, sheet_.objectMask);
      });
      if (std::any_of(sheet_.panels.begin(), sheet_.panels.end(), [](const PanelRender& p) { return p.maps.available; }))
        sheet_.flipNoiseFloor = flipNoiseFloor(m->replicates, sheet_.objectMask);
      if (!sheet_.noiseFloor.empty && sheet_.noiseFloor.figures.compared)
        sheet_.noiseFloor.maps = errorMaps(sheet_.noiseFloor.replicates, m->replicates, sheet_.objectMask);
    }
    sheet_.grid = RgbImage(w_ * int(sheet_.panels.size()), h_);
    for (size_t k = 0; k < sheet_.panels.size(); ++k)
      for (int y = 0; y < h_; ++y)
        std::copy_n(sheet_.panels[k].image.at(0, y), 3 * w_, sheet_.grid.at(int(k) * w_, y));
  }

  // The replicates' mean, pixel by pixel.
  static RgbImage meanOf(const std::vector<RgbImage>& replicates, int w, int h) {
    RgbImage mean(w, h);
    for (size_t i = 0; i < mean.pixels.size(); ++i) {
      double sum = 0.0;
      for (const RgbImage& r : replicates) sum += r.pixels[i];
      mean.pixels[i] = float(sum / double(replicates.size()));
    }
    return mean;
  }

  const SheetScene& scene_;
  const MaterialFile& material_;
  std::shared_ptr<const MerlTable> measured_;
  const std::string& measuredNote_;
  const SheetSettings& settings_;
  const int w_, h_;
  Sheet sheet_;
  std::vector<RenderScene> scenes_;  // of the panels with a BRDF
  std::vector<size_t> rendered_;     // the panel of each scene
  int measuredScene_ = -1;           // the measured panel's scene, if it has one
  int done_ = 0;                     // samples per replicate so far
  Comparison figures_;
  double widest_ = std::numeric_limits<double>::infinity();
};

}  // namespace

Sheet renderSheet(const SheetScene& scene, const MaterialFile& material, std::shared_ptr<const MerlTable> measured,
                  const std::string& measuredNote, const SheetSettings& settings) {
  return SheetRender(scene, material, std::move(measured), measuredNote, settings).run();
}

}  // namespace glossy
