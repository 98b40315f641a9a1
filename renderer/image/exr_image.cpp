#include "renderer/image/exr_image.h"

#include "materials/core/input_error.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <random>
#include <stdexcept>

namespace glossy {

void writeExr(const std::filesystem::path& path, const RgbImage& image, const std::vector<ImageAttribute>& attributes,
              PixelType type) {
  // OIIO picks the format from the extension, so the temporary keeps ".exr"; a hidden random name keeps
  // concurrent writers of one target apart.
  std::random_device rd;
  std::string tmpName = ".";
  tmpName.append(path.stem().string()).append(".tmp").append(std::to_string(rd() % 1000000)).append(".exr");
  const std::filesystem::path tmp = path.parent_path() / tmpName;
  auto fail = [&](const std::string& why) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    return std::runtime_error(path.string() + ": cannot write EXR: " + why);
  };

  auto out = OIIO::ImageOutput::create(tmp.string());
  if (!out) throw fail(OIIO::geterror());
  OIIO::ImageSpec spec(image.width, image.height, 3, type == PixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  for (const ImageAttribute& a : attributes) {
    if (auto s = std::get_if<std::string>(&a.value)) spec.attribute(a.name, *s);
    if (auto i = std::get_if<int>(&a.value)) spec.attribute(a.name, *i);
    if (auto f = std::get_if<float>(&a.value)) spec.attribute(a.name, *f);
  }
  if (!out->open(tmp.string(), spec)) throw fail(out->geterror());
  if (!out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data())) throw fail(out->geterror());
  if (!out->close()) throw fail(out->geterror());
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw fail("rename: " + ec.message());
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
