// Cutting a sheet's PNG into the site's images (sheet_images.h).
#include "renderer/report/sheet_images.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/image/exr_image.h"
#include "renderer/image/image_input.h"
#include "renderer/report/site_layout.h"
#include "renderer/sheet/sheet_record.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstring>
#include <fstream>

namespace glossy::report {

namespace {

// The box x, y, w × h of the image, as its own pixels.
std::vector<unsigned char> cut(const SheetPixels& from, int x, int y, int w, int h) {
  std::vector<unsigned char> out(size_t(w) * size_t(h) * 3);
  for (int row = 0; row < h; ++row)
    std::memcpy(&out[size_t(row) * size_t(w) * 3], &from.rgb[(size_t(y + row) * size_t(from.width) + size_t(x)) * 3], size_t(w) * 3);
  return out;
}

// Whether the PNG's chunks run whole from its signature to IEND at the file's end. libpng reports a file cut
// short on stderr before failing, which would make the error more than one line; this finds it first.
bool pngChunksAreWhole(const std::filesystem::path& png) {
  std::ifstream in(png, std::ios::binary);
  std::error_code ec;
  const uint64_t size = std::filesystem::file_size(png, ec);
  char head[8];
  if (!in || ec || !in.read(head, 8) || std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) != 0) return false;
  for (uint64_t at = 8; at + 12 <= size;) {
    unsigned char chunk[8];
    if (!in.read(reinterpret_cast<char*>(chunk), 8)) return false;
    const uint64_t length = uint64_t(chunk[0]) << 24 | uint64_t(chunk[1]) << 16 | uint64_t(chunk[2]) << 8 | chunk[3];
    at += 12 + length;  // length, type, data, CRC: at most 2^32 + 11 more, no overflow
    if (at > size) return false;
    if (std::memcmp(chunk + 4, "IEND", 4) == 0) return true;
    in.seekg(std::streamoff(at), std::ios::beg);
  }
  return false;
}

}  // namespace

SheetPixels readSheetPixels(const SheetRecord& sheet) {
  if (!pngChunksAreWhole(sheet.png)) throw InputError(sheet.png.string() + ": not a whole PNG (cut short?)");
  auto in = openImageFile(sheet.png, "PNG");
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width != sheet.imageWidth || spec.height != sheet.pngHeight)
    throw InputError(sheet.png.string() + ": changed since it was checked");
  SheetPixels p;
  p.width = spec.width;
  p.height = spec.height;
  p.rgb.resize(size_t(p.width) * size_t(p.height) * 3);
  // The first three channels as 8-bit: a grey or RGBA PNG reads as RGB too.
  const int channels = std::min(spec.nchannels, 3);
  if (channels == 3) {
    if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, p.rgb.data()))
      throw InputError(sheet.png.string() + ": cannot read its pixels: " + printableLine(in->geterror()));
  } else {
    std::vector<unsigned char> grey(size_t(p.width) * size_t(p.height));
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, grey.data()))
      throw InputError(sheet.png.string() + ": cannot read its pixels: " + printableLine(in->geterror()));
    for (size_t i = 0; i < grey.size(); ++i) p.rgb[3 * i] = p.rgb[3 * i + 1] = p.rgb[3 * i + 2] = grey[i];
  }
  return p;
}

void writeSheetImages(const SheetRecord& sheet, const SheetPixels& pixels, const std::filesystem::path& folder) {
  for (const PanelRecord& p : sheet.panels)
    writeRgb8(folder / layout::panelImage(p.layer), p.width, p.height, cut(pixels, p.x, p.y, p.width, p.height));
  if (sheet.panelsBottom < pixels.height)
    writeRgb8(folder / layout::sheetLowerImage(), pixels.width, pixels.height - sheet.panelsBottom,
              cut(pixels, 0, sheet.panelsBottom, pixels.width, pixels.height - sheet.panelsBottom));
}

}  // namespace glossy::report
