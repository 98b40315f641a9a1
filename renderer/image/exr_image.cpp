#include "renderer/image/exr_image.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "renderer/util/notes.h"
#include "materials/core/text.h"
#include "renderer/image/image_input.h"
#include "renderer/util/memory.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace glossy {

namespace {

// Encodes the image in memory (OIIO picks the format from the extension), then writes it atomically.
void writeAtomically(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc dataType,
                     const void* data) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto out = OIIO::ImageOutput::create(path.string(), &memory);
  if (!out) throw std::runtime_error(path.string() + ": cannot write image: " + OIIO::geterror());
  if (!out->open(path.string(), spec) || !out->write_image(dataType, data) || !out->close())
    throw std::runtime_error(path.string() + ": cannot write image: " + out->geterror());
  writeFileAtomically(path, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

// Opens an image to read (image_input.h), its size one that fits in memory.
std::unique_ptr<OIIO::ImageInput> openImage(const std::filesystem::path& path) {
  auto in = openImageFile(path, "image");
  const OIIO::ImageSpec& spec = in->spec();
  // The product of the header's counts in floating point (OpenImageIO keeps them as int).
  const double bytes = double(spec.width) * double(spec.height) * 3.0 * sizeof(float);
  if (const double have = physicalMemoryBytes(); have > 0.0 && bytes > have)
    throw InputError(path.string() + formatted(": %dx%d pixels need %.3g GB, more than the %.3g GB of memory here", spec.width,
                                               spec.height, bytes / 1e9, have / 1e9));
  return in;
}

void addAttributes(OIIO::ImageSpec& spec, const std::vector<ImageAttribute>& attributes) {
  for (const ImageAttribute& a : attributes) std::visit([&](const auto& value) { spec.attribute(a.name, value); }, a.value);
}

}  // namespace

void writeExr(const std::filesystem::path& path, const RgbImage& image, const std::vector<ImageAttribute>& attributes,
              PixelType type) {
  writeLayeredExr(path, {{"", &image}}, attributes, type);
}

void writeLayeredExr(const std::filesystem::path& path, const std::vector<ExrLayer>& layers,
                     const std::vector<ImageAttribute>& attributes, PixelType type) {
  if (layers.empty()) throw std::runtime_error(path.string() + ": no layers to write");
  const int w = layers.front().image->width, h = layers.front().image->height;
  int n = 0;
  for (const ExrLayer& l : layers) n += l.greyscale ? 1 : 3;
  OIIO::ImageSpec spec(w, h, n, type == PixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames.clear();
  for (const ExrLayer& l : layers)
    for (const char* c : l.greyscale ? std::vector<const char*>{"Y"} : std::vector<const char*>{"R", "G", "B"})
      spec.channelnames.push_back(l.prefix.empty() ? c : l.prefix + "." + c);
  spec.attribute("compression", "zip");
  addAttributes(spec, attributes);
  // No Inf or NaN in the file: a value beyond the type's largest finite one is written as that (half's is
  // 65504, which bright light easily exceeds), NaN as 0, and the pixels so changed are counted in the metadata.
  const float largest = type == PixelType::Half ? kLargestHalf : std::numeric_limits<float>::max();
  std::vector<float> pixels(size_t(w) * size_t(h) * size_t(n), 0.0f);
  std::vector<char> changed(size_t(w) * size_t(h), 0);
  int first = 0;  // the layer's first channel
  for (const ExrLayer& l : layers) {
    const RgbImage& img = *l.image;
    const int channels = l.greyscale ? 1 : 3;
    if (l.x < 0 || img.height != h || l.x + img.width > w)
      throw std::runtime_error(path.string() + ": layer " + l.prefix + " does not fit the file");
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < img.width; ++x) {
        const size_t p = size_t(y) * size_t(w) + size_t(l.x + x);
        for (int c = 0; c < channels; ++c) {
          const float v = img.at(x, y)[c];
          const float out = std::isnan(v) ? 0.0f : std::clamp(v, -largest, largest);
          changed[p] |= !(out == v);
          pixels[p * size_t(n) + size_t(first + c)] = out;
        }
      }
    first += channels;
  }
  const int64_t clamped = std::count(changed.begin(), changed.end(), 1);
  const int count = int(std::min<int64_t>(clamped, INT32_MAX));
  if (type == PixelType::Half) spec.attribute("glossy:halfClampedPixels", count);
  else if (clamped > 0) spec.attribute("glossy:nonFinitePixels", count);
  writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, pixels.data());
  // Said, not only recorded: a clipped highlight looks like any other.
  if (type == PixelType::Half && clamped > 0)
    note(formatted("%s: %lld of %lld pixels had a value above 65504, the largest half, written as 65504 (a float EXR keeps them)",
                   path.string().c_str(), (long long)clamped, (long long)changed.size()));
  else if (clamped > 0)
    note(formatted("%s: %lld of %lld pixels were not finite (an overflow or a NaN), written as the largest float or 0",
                   path.string().c_str(), (long long)clamped, (long long)changed.size()));
}

void writeRgb8(const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgb) {
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  writeAtomically(path, spec, OIIO::TypeDesc::UINT8, rgb.data());
}

RgbImage readRgbImage(const std::filesystem::path& path) {
  const auto in = openImage(path);
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3) throw InputError(path.string() + ": needs 3 channels, has " + std::to_string(spec.nchannels));
  RgbImage image(spec.width, spec.height);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw InputError(path.string() + ": cannot read image: " + in->geterror());
  return image;
}

std::string readImageAttribute(const std::filesystem::path& path, const std::string& name) {
  const auto in = openImage(path);
  const OIIO::ParamValue* p = in->spec().find_attribute(name);
  return p ? p->get_string() : std::string();
}

RgbImage readImageLayer(const std::filesystem::path& path, const std::string& prefix) {
  const auto in = openImage(path);
  const OIIO::ImageSpec& spec = in->spec();
  const int first = spec.channelindex(prefix + ".R");
  if (first < 0 || spec.channelindex(prefix + ".B") != first + 2)
    throw InputError(path.string() + ": has no layer '" + prefix + "'");
  RgbImage image(spec.width, spec.height);
  if (!in->read_image(0, 0, first, first + 3, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw InputError(path.string() + ": cannot read layer '" + prefix + "': " + in->geterror());
  return image;
}

}  // namespace glossy
