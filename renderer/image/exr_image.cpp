#include "renderer/image/exr_image.h"

#include "materials/core/input_error.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <random>
#include <stdexcept>

namespace glossy {

namespace {

// Writes through a hidden temporary beside the target (OIIO picks the format from the extension, so it
// keeps the target's), renamed into place; a random name keeps concurrent writers of one target apart.
void writeAtomically(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc dataType,
                     const void* data) {
  std::random_device rd;
  std::string tmpName = ".";
  tmpName.append(path.stem().string()).append(".tmp").append(std::to_string(rd() % 1000000)).append(path.extension().string());
  const std::filesystem::path tmp = path.parent_path() / tmpName;
  auto fail = [&](const std::string& why) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    return std::runtime_error(path.string() + ": cannot write image: " + why);
  };
  auto out = OIIO::ImageOutput::create(tmp.string());
  if (!out) throw fail(OIIO::geterror());
  if (!out->open(tmp.string(), spec)) throw fail(out->geterror());
  if (!out->write_image(dataType, data)) throw fail(out->geterror());
  if (!out->close()) throw fail(out->geterror());
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw fail("rename: " + ec.message());
}

void addAttributes(OIIO::ImageSpec& spec, const std::vector<ImageAttribute>& attributes) {
  for (const ImageAttribute& a : attributes) {
    if (auto s = std::get_if<std::string>(&a.value)) spec.attribute(a.name, *s);
    if (auto i = std::get_if<int>(&a.value)) spec.attribute(a.name, *i);
    if (auto f = std::get_if<float>(&a.value)) spec.attribute(a.name, *f);
  }
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
  const int n = int(layers.size()) * 3;
  OIIO::ImageSpec spec(w, h, n, type == PixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.channelnames.clear();
  for (const ExrLayer& l : layers)
    for (const char* c : {"R", "G", "B"}) spec.channelnames.push_back(l.prefix.empty() ? c : l.prefix + "." + c);
  spec.attribute("compression", "zip");
  addAttributes(spec, attributes);
  std::vector<float> pixels(size_t(w) * size_t(h) * size_t(n));
  for (size_t k = 0; k < layers.size(); ++k) {
    const RgbImage& img = *layers[k].image;
    if (img.width != w || img.height != h) throw std::runtime_error(path.string() + ": layers of different sizes");
    for (size_t p = 0; p < size_t(w) * size_t(h); ++p)
      for (int c = 0; c < 3; ++c) pixels[p * n + k * 3 + c] = img.pixels[p * 3 + c];
  }
  writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, pixels.data());
}

void writeRgb8(const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgb) {
  const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  writeAtomically(path, spec, OIIO::TypeDesc::UINT8, rgb.data());
}

RgbImage readRgbImage(const std::filesystem::path& path) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(path.string() + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.nchannels < 3) throw InputError(path.string() + ": needs 3 channels, has " + std::to_string(spec.nchannels));
  RgbImage image(spec.width, spec.height);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, image.pixels.data()))
    throw InputError(path.string() + ": cannot read image: " + in->geterror());
  return image;
}

std::string readImageAttribute(const std::filesystem::path& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(path.string() + ": cannot read image: " + OIIO::geterror());
  const OIIO::ParamValue* p = in->spec().find_attribute(name);
  return p ? p->get_string() : std::string();
}

}  // namespace glossy

namespace glossy {

RgbImage readImageLayer(const std::filesystem::path& path, const std::string& prefix) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) throw InputError(path.string() + ": cannot read image: " + OIIO::geterror());
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
