// Cutting a sheet's panels out of its EXR into PNGs (panel_png.h).
#include "renderer/report/panel_png.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/image/colour_maps.h"
#include "renderer/image/exr_image.h"
#include "renderer/report/sheet_record.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace glossy::report {

void writePanelPngs(const std::filesystem::path& exr, const std::vector<const PanelRecord*>& panels, double exposure,
                    const std::function<std::filesystem::path(const PanelRecord&)>& png) {
  if (panels.empty()) return;
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) throw InputError(exr.string() + ": cannot read: " + printableLine(OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  std::vector<std::array<int, 3>> rgb;  // per panel: its layer's R, G, B channels
  for (const PanelRecord* p : panels) {
    const std::array<int, 3> c = {spec.channelindex(p->layer + ".R"), spec.channelindex(p->layer + ".G"), spec.channelindex(p->layer + ".B")};
    if (c[0] < 0 || c[1] < 0 || c[2] < 0 || p->x + p->width > spec.width || p->y + p->height > spec.height)
      throw InputError(exr.string() + ": panel '" + p->layer + "' has no layer inside the image");
    rgb.push_back(c);
  }
  std::vector<std::vector<unsigned char>> out(panels.size());
  for (size_t k = 0; k < panels.size(); ++k) out[k].resize(size_t(panels[k]->width) * size_t(panels[k]->height) * 3);

  const double scale = std::exp2(exposure);
  // A band of rows at a time: a few compressed blocks, every channel, bounded memory for any sheet size.
  constexpr int kBand = 32;
  std::vector<float> band(size_t(kBand) * size_t(spec.width) * size_t(channels));
  for (int y0 = spec.y; y0 < spec.y + spec.height; y0 += kBand) {
    const int y1 = std::min(y0 + kBand, spec.y + spec.height);
    if (!in->read_scanlines(0, 0, y0, y1, 0, 0, channels, OIIO::TypeDesc::FLOAT, band.data()))
      throw InputError(exr.string() + ": cannot read its pixels: " + printableLine(in->geterror()));
    for (size_t k = 0; k < panels.size(); ++k) {
      const PanelRecord& p = *panels[k];
      for (int y = std::max(y0, spec.y + p.y); y < std::min(y1, spec.y + p.y + p.height); ++y)
        for (int x = 0; x < p.width; ++x) {
          const float* px = &band[(size_t(y - y0) * size_t(spec.width) + size_t(p.x + x)) * size_t(channels)];
          unsigned char* o = &out[k][(size_t(y - spec.y - p.y) * size_t(p.width) + size_t(x)) * 3];
          // srgbEncode clamps to [0, 1] and makes NaN black (an Inf from the scale is clamped too).
          for (int c = 0; c < 3; ++c) o[c] = (unsigned char)std::lround(255.0 * srgbEncode(double(px[rgb[k][size_t(c)]]) * scale));
        }
    }
  }
  for (size_t k = 0; k < panels.size(); ++k) writeRgb8(png(*panels[k]), panels[k]->width, panels[k]->height, out[k]);
}

}  // namespace glossy::report
