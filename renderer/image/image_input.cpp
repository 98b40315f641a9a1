#include "renderer/image/image_input.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"
#include "renderer/image/exr_preflight.h"

namespace glossy {

std::unique_ptr<OIIO::ImageInput> openImageFile(const std::filesystem::path& path, std::string_view kind) {
  const std::string name = path.string(), what(kind);
  requireInputFile(path, kind);
  preflightExr(path);
  const std::string extension = path.extension().string();
  if (extension.size() < 2) throw InputError(name + ": " + what + " has no extension (.exr, .png, ...) to choose its reader by");
  auto in = OIIO::ImageInput::create(extension.substr(1));
  if (!in) throw InputError(printableLine(name + ": cannot read " + what + ": " + OIIO::geterror()));
  if (OIIO::ImageSpec opened; !in->open(name, opened))
    throw InputError(printableLine(name + ": cannot read " + what + ": " + in->geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.depth != 1 || spec.nchannels <= 0)
    throw InputError(name + formatted(": an image of %dx%dx%d with %d channels is not a %s glossy reads", spec.width, spec.height,
                                      spec.depth, spec.nchannels, what.c_str()));
  return in;
}

}  // namespace glossy
