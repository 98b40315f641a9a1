// A sheet as a labelled PNG: the panels side by side (sRGB at the exposure), each with its label, fit,
// parameters and figures beneath, and the error maps' row where there is a measured panel.
#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"
#include "renderer/image/colour_maps.h"
#include "renderer/util/notes.h"

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

const float kStrip[3] = {0.12f, 0.12f, 0.12f}, kEmpty[3] = {0.25f, 0.25f, 0.25f}, kWhite[3] = {0.95f, 0.95f, 0.95f},
            kGrey[3] = {0.7f, 0.7f, 0.7f}, kOrange[3] = {1.0f, 0.6f, 0.2f}, kBackground[3] = {0.2f, 0.2f, 0.2f};

// The picture being drawn, with its panel size and fonts.
struct Picture {
  OIIO::ImageBuf& buf;
  int w, h;  // a panel's size
  int fontSize, small, strip;
  const std::string& font;

  void text(const std::string& line, int x, int y, int size, OIIO::cspan<float> colour, int width) {
    OIIO::ImageBufAlgo::render_text(buf, x, y, fitted(line, width, size, font), size, font, colour);
  }
};

// Panel k's image, sRGB at the exposure (grey where it is empty).
void drawPanel(Picture& pic, int k, const PanelRender& p, double scale) {
  if (p.empty) {
    OIIO::ImageBufAlgo::fill(pic.buf, kEmpty, OIIO::ROI(k * pic.w, (k + 1) * pic.w, 0, pic.h));
    return;
  }
  for (int y = 0; y < pic.h; ++y)
    for (int x = 0; x < pic.w; ++x) {
      const float* px = p.image.at(x, y);
      const float v[3] = {srgbEncode(px[0] * scale), srgbEncode(px[1] * scale), srgbEncode(px[2] * scale)};
      pic.buf.setpixel(k * pic.w + x, y, v, 3);
    }
}

// The line under a panel's label: its figures against the measured panel, or why it has none, or the
// measured panel's database.
std::string figuresLine(const PanelRender& p, int w) {
  if (p.empty) return p.panel.fit.empty() ? "no MERL data (--merl-dir)" : "no fit";
  if (p.figures.hasCi)
    // Narrow panels get the figures without their names. ASCII only: OpenImageIO's text drops the high
    // bit of every byte, so "±" would come out as "1".
    return formatted(w >= 200 ? "rRMSE %.3f +/-%.3f  lum x%.2f" : "%.3f+/-%.3f x%.2f", p.figures.relativeRmse,
                     p.figures.relativeRmseCi.halfWidth(), p.figures.luminanceRatio);
  if (p.figures.compared)
    return formatted(w >= 120 ? "rRMSE %.3f (noisy)  lum x%.2f" : "%.3f? x%.2f",
                     p.figures.available ? p.figures.relativeRmse : p.figures.noisyRelativeRmse, p.figures.luminanceRatio);
  if (!p.panel.fit.empty()) return "no measured panel";
  return databaseCaption(p.note);
}

// Panel k's label strip: its name, figures, BRDF errors and ꟻLIP.
void drawLabels(Picture& pic, int k, const PanelRender& p) {
  const int w = pic.w, fontSize = pic.fontSize, small = pic.small;
  const auto label = [&](const std::string& line, int y, int size, OIIO::cspan<float> colour) {
    pic.text(line, k * w + 3, pic.h + y, size, colour, w - 6);
  };
  const std::string second = figuresLine(p, w);
  label(p.panel.label, fontSize + 2, fontSize, kWhite);
  if (!second.empty()) label(second, 2 * fontSize + 5, small, kGrey);
  if (p.brdfE1 >= 0.0) label(formatted(w >= 120 ? "E1 %.3g  E2 %.3g" : "%.2g %.2g", p.brdfE1, p.brdfE2), 3 * fontSize + 7, small, kGrey);
  if (p.maps.available)
    label(p.maps.hasCi ? formatted(w >= 120 ? "FLIP %.3f +/-%.3f" : "F %.3f+/-%.3f", p.maps.flip, p.maps.flipCi.halfWidth())
                           : formatted("FLIP %.3f", p.maps.flip),
          4 * fontSize + 9, small, kGrey);
}

// The maps' legend, under the measured panel (column k): a colour bar over the map's range and what it
// shows; not in thumbnails, where it would not be legible.
void drawLegend(Picture& pic, int k, int top) {
  const int w = pic.w, h = pic.h, fontSize = pic.fontSize, small = pic.small;
  OIIO::ImageBufAlgo::fill(pic.buf, kStrip, OIIO::ROI(k * w, (k + 1) * w, top, top + h));
  if (w < 96 || h < 64) return;
  const int barLeft = k * w + w / 10, barWidth = w - w / 5, barTop = top + h / 2 - fontSize, barHeight = std::max(6, h / 12);
  for (int x = 0; x < barWidth; ++x) {
    const DisplayColour c = divergingColour(2.0 * (x + 0.5) / barWidth - 1.0);
    for (int y = 0; y < barHeight; ++y) pic.buf.setpixel(barLeft + x, barTop + y, c.data(), 3);
  }
  const std::string range = formatted("%.0f%%", 100.0 * kRelativeDifferenceRange);
  pic.text("-" + range, barLeft - 2, barTop + barHeight + small + 2, small, kGrey, w / 3);
  pic.text("0", barLeft + barWidth / 2 - small / 4, barTop + barHeight + small + 2, small, kGrey, w / 3);
  pic.text("+" + range, barLeft + barWidth - 3 * small, barTop + barHeight + small + 2, small, kGrey, w / 3);
  pic.text("luminance vs measured:", k * w + 3, top + fontSize + 2, small, kWhite, w - 6);
  pic.text("(model - meas.) / meas.", k * w + 3, top + 2 * fontSize + 4, small, kGrey, w - 6);
  pic.text("darker  <  >  brighter", k * w + 3, barTop + barHeight + 2 * small + 6, small, kGrey, w - 6);
}

// Model panel k's error map in the second row: where it is brighter (red) or darker (blue) than the
// measured panel, over the object's pixels.
void drawMap(Picture& pic, int k, const PanelRender& p, const std::vector<char>& objectMask, int top) {
  const int w = pic.w, h = pic.h;
  if (!p.maps.available) {
    OIIO::ImageBufAlgo::fill(pic.buf, kEmpty, OIIO::ROI(k * w, (k + 1) * w, top, top + h));
    return;
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      if (!objectMask[i]) {
        pic.buf.setpixel(k * w + x, top + y, kBackground, 3);
        continue;
      }
      const DisplayColour c = divergingColour(p.maps.relativeDifference[i] / kRelativeDifferenceRange);
      pic.buf.setpixel(k * w + x, top + y, c.data(), 3);
    }
}

// The strip under the maps, across the whole width: what noise alone shows, and the warnings.
void drawNotes(Picture& pic, const Sheet& sheet, int top, int width) {
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
  pic.text(line, 3, top + pic.small + 2, pic.small, kGrey, width - 6);
  std::string warnings;
  for (const std::string& w : sheet.warnings) warnings.append(warnings.empty() ? "warning: " : "; ").append(w);
  pic.text(warnings.empty() ? std::string("no warnings") : warnings, 3, top + 2 * pic.small + 8, pic.small,
           warnings.empty() ? OIIO::cspan<float>(kGrey) : OIIO::cspan<float>(kOrange), width - 6);
}

}  // namespace

SheetPngSize sheetPngSize(int panelWidth, int panelHeight, int panels) {
  const int plain = panelHeight + labelStrip(panelWidth);
  return {panelWidth * panels, plain, plain + panelHeight + noteStrip(panelWidth)};
}

void writeSheetPng(const Sheet& sheet, const std::filesystem::path& path, double exposure, const std::string& fontPath) {
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  const int n = int(sheet.panels.size());
  const bool mapRow = sheet.hasMeasured();
  const SheetPngSize size = sheetPngSize(w, h, n);
  const int height = mapRow ? size.heightWithMaps : size.height;
  OIIO::ImageBuf buf(OIIO::ImageSpec(size.width, height, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::fill(buf, kStrip);
  Picture pic{buf, w, h, labelFontSize(w), smallFontSize(w), labelStrip(w), fontPath};
  const double scale = std::exp2(exposure);
  for (int k = 0; k < n; ++k) drawPanel(pic, k, sheet.panels[size_t(k)], scale);
  for (int k = 0; k < n; ++k) drawLabels(pic, k, sheet.panels[size_t(k)]);
  if (mapRow) {
    const int top = h + pic.strip;
    for (int k = 0; k < n; ++k) {
      const PanelRender& p = sheet.panels[size_t(k)];
      if (p.panel.fit.empty()) drawLegend(pic, k, top);
      else drawMap(pic, k, p, sheet.objectMask, top);
    }
    drawNotes(pic, sheet, top + h, size.width);
  }
  if (buf.has_error()) note(path.string() + ": labels not drawn: " + buf.geterror());
  std::vector<unsigned char> rgb(size_t(w * n) * size_t(height) * 3);
  if (!buf.get_pixels(buf.roi(), OIIO::TypeDesc::UINT8, rgb.data())) throw std::runtime_error(path.string() + ": " + buf.geterror());
  writeRgb8(path, w * n, height, rgb);
}

}  // namespace glossy
