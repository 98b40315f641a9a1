// A sheet as a labelled PNG: the panels side by side (sRGB at the exposure), each with its label, fit,
// parameters and figures beneath, and the error maps' row where there is a measured panel.
#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"
#include "renderer/image/colour_maps.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace glossy {

namespace {

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

}  // namespace glossy
