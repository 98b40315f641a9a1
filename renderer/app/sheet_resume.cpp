#include "renderer/app/sheet_resume.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "materials/params/material_file.h"
#include "renderer/image/exr_image.h"
#include "renderer/image/image_input.h"
#include "renderer/sheet/sheet.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>

namespace glossy::app {

std::string contentDigest(const std::filesystem::path& path) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : readInputFile(path, kMaxMaterialFileBytes, "material file")) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
  return formatted("%016llx", static_cast<unsigned long long>(h));
}

std::string whyIncomplete(const std::filesystem::path& exr, const std::string& settings, const SheetSettings& sheet) {
  std::error_code ec;
  const std::filesystem::path png = std::filesystem::path(exr).replace_extension(".png");
  if (!std::filesystem::is_regular_file(exr, ec)) return "no EXR";
  if (!std::filesystem::exists(png, ec)) return "no PNG";
  // The PNG is trusted only if it opens as one, at the size these settings give it.
  try {
    std::unique_ptr<OIIO::ImageInput> in;
    try {
      in = openImageFile(png, "PNG");
    } catch (const InputError&) {
      return "PNG that is not a PNG image";
    }
    const SheetPngSize size = sheetPngSize(sheet.width, sheet.height, int(sheet.panels.size()));
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width != size.width || (spec.height != size.height && spec.height != size.heightWithMaps))
      return formatted("PNG of %dx%d, not the %dx%d (or %dx%d) of these settings", spec.width, spec.height, size.width,
                       size.height, size.width, size.heightWithMaps);
  } catch (const std::exception& e) {
    return std::string("unreadable PNG (") + e.what() + ")";
  }
  try {
    const std::string made = readImageAttribute(exr, kSettingsAttribute);
    if (made != settings) return made.empty() ? "EXR without glossy:settings" : "made with other settings";
    // Reading every layer's pixels also catches a file cut short after its header.
    for (const SheetPanel& p : sheet.panels) readImageLayer(exr, p.layer);
  } catch (const std::exception& e) {
    return std::string("unreadable EXR (") + e.what() + ")";
  }
  return "";
}

size_t removeStaleTemporaries(const std::filesystem::path& exr) {
  std::error_code ec;
  size_t removed = 0;
  const std::filesystem::path png = std::filesystem::path(exr).replace_extension(".png");
  const std::filesystem::path folder = exr.has_parent_path() ? exr.parent_path() : std::filesystem::path(".");
  for (const auto& e : std::filesystem::directory_iterator(folder, ec))
    if ((isTemporaryOf(e.path(), exr) || isTemporaryOf(e.path(), png)) && e.is_regular_file(ec) && std::filesystem::remove(e.path(), ec))
      ++removed;
  return removed;
}

}  // namespace glossy::app
