// Plot pictures for the site (plot_picture.h).
#include "renderer/report/plot_picture.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/image/image_input.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <cstdint>

namespace glossy::report {

namespace {

constexpr int64_t kMaxPicturePixels = int64_t(1) << 28;

bool canWriteWebp() {
  static const bool can = [] { return OIIO::ImageOutput::create("webp") != nullptr; }();
  return can;
}

}  // namespace

void checkPlotPicture(const std::filesystem::path& file) {
  auto in = openImageFile(file, "plot picture");
  const OIIO::ImageSpec& s = in->spec();
  if (s.width <= 0 || s.height <= 0 || int64_t(s.width) * int64_t(s.height) > kMaxPicturePixels || s.nchannels < 1 || s.nchannels > 4)
    throw InputError(file.string() + formatted(": %d x %d pixels of %d channels, not a plot picture the report handles", s.width, s.height,
                                               s.nchannels));
}

std::string sitePictureName(const std::string& png, const std::set<std::string>& taken) {
  const std::string ext = canWriteWebp() ? ".webp" : ".png";
  const std::string name = std::filesystem::path(png).replace_extension(ext).string();
  return name == png || !taken.count(name) ? name : png + ext;
}

void writeSitePicture(const std::filesystem::path& from, const std::filesystem::path& to) {
  OIIO::ImageBuf source(from.string());
  if (!source.read(0, 0, true, OIIO::TypeDesc::UINT8)) throw InputError(from.string() + ": cannot read its pixels: " + printableLine(source.geterror()));
  // RGB, or RGBA when it has alpha: a grey picture's channel thrice.
  const int n = source.nchannels();
  const std::vector<int> order = n >= 4 ? std::vector<int>{0, 1, 2, 3} : n == 3 ? std::vector<int>{0, 1, 2}
                                 : n == 2 ? std::vector<int>{0, 0, 0, 1} : std::vector<int>{0, 0, 0};
  OIIO::ImageBuf rgb = OIIO::ImageBufAlgo::channels(source, int(order.size()), order);
  OIIO::ImageBuf shown = rgb;
  const OIIO::ImageSpec& s = rgb.spec();
  if (s.width > kSitePictureWidth) {
    const int height = std::max(1, int(std::lround(double(s.height) * kSitePictureWidth / s.width)));
    shown = OIIO::ImageBufAlgo::resize(rgb, "triangle", 0.0f, OIIO::ROI(0, kSitePictureWidth, 0, height, 0, 1, 0, s.nchannels));
  }
  if (shown.has_error()) throw std::runtime_error(from.string() + ": cannot scale: " + shown.geterror());
  OIIO::ImageSpec spec(shown.spec().width, shown.spec().height, shown.nchannels(), OIIO::TypeDesc::UINT8);
  if (to.extension() == ".webp") spec.attribute("compression", "webp:90");
  std::vector<unsigned char> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  shown.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, pixels.data());
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto out = OIIO::ImageOutput::create(to.string(), &memory);
  if (!out || !out->open(to.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !out->close())
    throw std::runtime_error(to.string() + ": cannot write: " + (out ? out->geterror() : OIIO::geterror()));
  writeFileAtomically(to, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

}  // namespace glossy::report
