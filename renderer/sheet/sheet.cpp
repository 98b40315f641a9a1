#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"
#include "materials/fitting/metric.h"
#include "materials/models/registry.h"
#include "renderer/camera/camera_rays.h"
#include "renderer/scene/material_binding.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

namespace glossy {

namespace {

double luminance(const float* p) { return glossy::luminance(Rgb(p[0], p[1], p[2])); }

// sRGB transfer function (IEC 61966-2-1) of a linear value, clamped to [0, 1].
float srgbEncode(double v) {
  v = std::clamp(v, 0.0, 1.0);
  return float(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

PanelRender renderPanel(const SheetScene& scene, const SheetPanel& panel, const Brdf& brdf, const SheetSettings& s) {
  PanelRender out;
  out.panel = panel;
  out.empty = false;
  std::vector<Brdf> brdfs = scene.baseBrdfs;
  for (size_t m = 0; m < brdfs.size(); ++m)
    if (scene.isObject[m]) brdfs[m] = brdf;
  const RenderScene rs{scene.description, scene.bvh, std::move(brdfs), brdf, scene.environment};
  RenderSettings r{.width = s.width, .height = s.height, .maxDepth = s.maxDepth, .seed = s.seed, .threads = s.threads,
                   .progress = s.progress && s.secondsPerPanel <= 0.0};
  const auto start = std::chrono::steady_clock::now();
  if (s.secondsPerPanel <= 0.0) {
    r.spp = s.spp;
    RenderStats stats;
    out.image = render(rs, *scene.camera, r, stats);
    out.spp = s.spp;
    out.droppedSamples = stats.droppedSamples;
  } else {
    // Progressive: passes of 1, 2, 4, … samples, each its own sample pattern (seeded by its first sample),
    // until the next pass would overrun the budget (it takes about twice the last one).
    out.image = RgbImage(s.width, s.height);
    int pass = 1;
    for (;;) {
      r.firstSample = out.spp;
      r.spp = pass;
      RenderStats stats;
      const RgbImage img = render(rs, *scene.camera, r, stats);
      const double wOld = double(out.spp) / (out.spp + pass), wNew = double(pass) / (out.spp + pass);
      for (size_t i = 0; i < img.pixels.size(); ++i)
        out.image.pixels[i] = float(wOld * out.image.pixels[i] + wNew * img.pixels[i]);
      out.spp += pass;
      out.droppedSamples += stats.droppedSamples;
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (elapsed + 2.0 * stats.seconds > s.secondsPerPanel) break;
      pass *= 2;
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

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

}  // namespace

SheetPanel SheetPanel::measured() { return {"measured", "Measured", ""}; }

SheetPanel SheetPanel::ofFit(const FitId& fit) {
  const ModelInfo* model = findModel(fit.model);
  std::string layer = fit.model + "_" + fit.metric;
  std::replace(layer.begin(), layer.end(), '-', '_');
  return {layer, std::string(model ? model->shortLabel : fit.model) + " " + fit.metric, fit.str()};
}

std::span<const SheetPanel> sheetPanels() {
  static const std::vector<SheetPanel> panels = [] {
    std::vector<SheetPanel> grid = {SheetPanel::measured()};
    for (const char* fit : {"microfacet:E2", "smooth:E2", "ashikhmin-shirley:E1", "ashikhmin-shirley:E2", "cook-torrance:E1", "cook-torrance:E2"})
      grid.push_back(SheetPanel::ofFit(FitId::parse(fit, "the sheet grid")));
    return grid;
  }();
  return panels;
}

const PanelRender* Sheet::measured() const {
  for (const PanelRender& p : panels)
    if (p.panel.fit.empty()) return &p;
  return nullptr;
}

SheetScene makeSheetScene(const SceneDescription& description, const EmbreeScene& bvh,
                          const Environment& environment, const Camera& camera) {
  SheetScene s{&description, &bvh, &environment, &camera, bindMaterials(description, std::nullopt).brdfs, {}};
  bool anyBound = false;
  for (const SceneMaterial& m : description.materials) anyBound = anyBound || !m.glossyMaterial.empty();
  for (const SceneMaterial& m : description.materials)
    s.isObject.push_back(!m.isEmissive() && (anyBound ? !m.glossyMaterial.empty() : true));
  return s;
}

Sheet renderSheet(const SheetScene& scene, const MaterialFile& material, std::shared_ptr<const MerlTable> measured,
                  const std::string& measuredNote, const SheetSettings& settings) {
  Sheet sheet;
  sheet.material = material.name;
  const int w = settings.width, h = settings.height;

  sheet.objectMask.resize(size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      Hit hit;
      const bool seen = scene.bvh->intersect(cameraRay(*scene.camera, w, h, Vec2(x + 0.5, y + 0.5)), hit);
      const int m = seen ? scene.description->meshes[hit.mesh].material : -1;
      sheet.objectMask[size_t(y) * w + x] = seen && (m < 0 || scene.isObject[size_t(m)]);
    }

  // The BRDF-space errors beside the image-space ones: the same E1/E2 as `glossy error`.
  std::optional<MetricData> e1, e2;
  if (measured) e1.emplace(*measured, Metric::E1), e2.emplace(*measured, Metric::E2);

  for (const SheetPanel& panel : settings.panels) {
    PanelRender r;
    r.panel = panel;
    if (panel.fit.empty()) {
      if (measured) r = renderPanel(scene, panel, Measured(measured), settings);
      r.note = measuredNote;
    } else if (const Fit* fit = material.find(FitId::parse(panel.fit, material.path.string()))) {
      const Brdf brdf = makeBrdf(*fit);
      r = renderPanel(scene, panel, brdf, settings);
      if (measured) r.brdfE1 = e1->error(brdf), r.brdfE2 = e2->error(brdf);
    } else {
      r.note = "no " + panel.fit + " fit in " + material.name;
    }
    if (r.empty) r.image = RgbImage(w, h);
    sheet.panels.push_back(std::move(r));
  }

  if (sheet.hasMeasured())
    for (PanelRender& p : sheet.panels) {
      if (p.empty || p.panel.fit.empty()) continue;
      p.relativeRmse = relativeRmse(p.image, sheet.measured()->image, sheet.objectMask);
      p.luminanceRatio = luminanceRatio(p.image, sheet.measured()->image, sheet.objectMask);
    }

  sheet.grid = RgbImage(w * int(sheet.panels.size()), h);
  for (size_t k = 0; k < sheet.panels.size(); ++k)
    for (int y = 0; y < h; ++y)
      std::copy_n(sheet.panels[k].image.at(0, y), 3 * w, sheet.grid.at(int(k) * w, y));
  return sheet;
}

double relativeRmse(const RgbImage& panel, const RgbImage& reference, const std::vector<char>& mask) {
  double err = 0.0, norm = 0.0;
  for (size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) continue;
    for (int c = 0; c < 3; ++c) {
      const double d = double(panel.pixels[3 * i + c]) - reference.pixels[3 * i + c];
      err += d * d;
      norm += double(reference.pixels[3 * i + c]) * reference.pixels[3 * i + c];
    }
  }
  return norm > 0.0 ? std::sqrt(err / norm) : -1.0;
}

double luminanceRatio(const RgbImage& panel, const RgbImage& reference, const std::vector<char>& mask) {
  double a = 0.0, b = 0.0;
  for (size_t i = 0; i < mask.size(); ++i)
    if (mask[i]) {
      a += luminance(&panel.pixels[3 * i]);
      b += luminance(&reference.pixels[3 * i]);
    }
  return b > 0.0 ? a / b : -1.0;
}

void writeSheetExr(const Sheet& sheet, const std::filesystem::path& path, std::vector<ImageAttribute> metadata, PixelType type) {
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  std::vector<RgbImage> placed;
  placed.reserve(sheet.panels.size());
  std::string names;
  for (size_t k = 0; k < sheet.panels.size(); ++k) {
    const PanelRender& p = sheet.panels[k];
    RgbImage img(sheet.grid.width, sheet.grid.height);
    for (int y = 0; y < h; ++y) std::copy_n(p.image.at(0, y), 3 * w, img.at(int(k) * w, y));
    placed.push_back(std::move(img));
    names += (names.empty() ? "" : ",") + p.panel.layer;
    const std::string key = "glossy:panel." + p.panel.layer;
    metadata.push_back({key + ".box", std::to_string(int(k) * w) + " 0 " + std::to_string(w) + " " + std::to_string(h)});
    metadata.push_back({key + ".label", p.panel.label});
    metadata.push_back({key + ".fit", p.panel.fit.empty() ? std::string("measured") : p.panel.fit});
    metadata.push_back({key + ".empty", int(p.empty)});
    if (!p.note.empty()) metadata.push_back({key + ".note", p.note});
    if (!p.empty) {
      metadata.push_back({key + ".spp", p.spp});
      metadata.push_back({key + ".seconds", float(p.seconds)});
      metadata.push_back({key + ".droppedSamples", int(std::min<uint64_t>(p.droppedSamples, INT32_MAX))});
    }
    if (p.relativeRmse >= 0.0) {
      metadata.push_back({"glossy:error." + p.panel.layer + ".relativeRmse", float(p.relativeRmse)});
      metadata.push_back({"glossy:error." + p.panel.layer + ".luminanceRatio", float(p.luminanceRatio)});
    }
    if (p.brdfE1 >= 0.0) {
      metadata.push_back({"glossy:error." + p.panel.layer + ".E1", float(p.brdfE1)});
      metadata.push_back({"glossy:error." + p.panel.layer + ".E2", float(p.brdfE2)});
    }
  }
  metadata.push_back({"glossy:panels", names});
  metadata.push_back({"glossy:panelSize", std::to_string(w) + "x" + std::to_string(h)});
  metadata.push_back({"glossy:errors", sheet.hasMeasured() ? std::string("relativeRmse, luminanceRatio: against the measured panel, over the object's pixels; "
                                                                       "E1, E2: the fit against the measured table on the grid ") + MetricGrid::describe()
                                                           : std::string("none: no measured panel")});
  std::vector<ExrLayer> layers = {{"", &sheet.grid}};
  for (size_t k = 0; k < sheet.panels.size(); ++k) layers.push_back({sheet.panels[k].panel.layer, &placed[k]});
  writeLayeredExr(path, layers, metadata, type);
}

void writeSheetPng(const Sheet& sheet, const std::filesystem::path& path, double exposure, const std::string& fontPath) {
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  const int n = int(sheet.panels.size());
  const int fontSize = std::clamp(w / 13, 9, 16);
  const int strip = 3 * fontSize + fontSize / 2 + 8;
  OIIO::ImageBuf buf(OIIO::ImageSpec(w * n, h + strip, 3, OIIO::TypeDesc::FLOAT));
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
  const int small = std::max(8, fontSize - 2);
  for (int k = 0; k < n; ++k) {
    const PanelRender& p = sheet.panels[size_t(k)];
    auto label = [&](const std::string& text, int y, int size, OIIO::cspan<float> colour) {
      OIIO::ImageBufAlgo::render_text(buf, k * w + 3, h + y, fitted(text, w - 6, size, fontPath), size, fontPath, colour);
    };
    std::string second;
    if (p.empty)
      second = p.panel.fit.empty() ? "no MERL data (--merl-dir)" : "no fit";
    else if (p.relativeRmse >= 0.0)
      // Narrow panels get the figures without their names.
      second = formatted(w >= 120 ? "rRMSE %.3f  lum x%.2f" : "%.3f x%.2f", p.relativeRmse, p.luminanceRatio);
    else if (!p.panel.fit.empty())
      second = "no measured panel";
    else
      second = p.note.find("NBRDF") != std::string::npos ? "MERL (NBRDF reconstr.)" : "MERL";
    label(p.panel.label, fontSize + 2, fontSize, white);
    if (!second.empty()) label(second, 2 * fontSize + 5, small, grey);
    if (p.brdfE1 >= 0.0) label(formatted(w >= 120 ? "E1 %.3g  E2 %.3g" : "%.2g %.2g", p.brdfE1, p.brdfE2), 3 * fontSize + 7, small, grey);
  }
  if (buf.has_error()) std::fprintf(stderr, "glossy: %s: labels not drawn: %s\n", path.string().c_str(), buf.geterror().c_str());
  std::vector<unsigned char> rgb(size_t(w * n) * size_t(h + strip) * 3);
  if (!buf.get_pixels(buf.roi(), OIIO::TypeDesc::UINT8, rgb.data())) throw std::runtime_error(path.string() + ": " + buf.geterror());
  writeRgb8(path, w * n, h + strip, rgb);
}

std::string errorTable(const Sheet& sheet) {
  std::ostringstream s;
  s << sheet.material << ": ";
  const std::string note = sheet.measured() ? sheet.measured()->note : "none in the grid";
  if (sheet.hasMeasured())
    s << "error of each model against the measured panel (" << note << "), over the object's pixels\n";
  else
    s << "no measured panel (" << note << "), so no errors against it\n";
  s << "  panel           spp   rel. RMSE   luminance ratio   BRDF E1   BRDF E2\n";
  for (const PanelRender& p : sheet.panels) {
    if (p.empty)
      s << formatted("  %-14s    -   %s\n", p.panel.label.c_str(), p.note.c_str());
    else if (p.relativeRmse >= 0.0)
      s << formatted("  %-14s %5d   %9.4f   %15.4f   %7.4f   %7.4f\n", p.panel.label.c_str(), p.spp, p.relativeRmse,
                     p.luminanceRatio, p.brdfE1, p.brdfE2);
    else
      s << formatted("  %-14s %5d   %9s   %15s\n", p.panel.label.c_str(), p.spp, "-", "-");
  }
  // Which model is closest: the smallest relative RMSE.
  const PanelRender* best = nullptr;
  for (const PanelRender& p : sheet.panels)
    if (p.relativeRmse >= 0.0 && (!best || p.relativeRmse < best->relativeRmse)) best = &p;
  if (best) s << "  closest: " << best->panel.label << "\n";
  return s.str();
}

}  // namespace glossy
