// Opening an image file to read, the one way every reader of glossy does it: the path must be a regular
// file (OpenImageIO would wait on a FIFO for ever and read a device without end), an OpenEXR's headers are
// checked first (renderer/image/exr_preflight.h), and only the reader of the file's extension is tried —
// ImageInput::open hands a file its reader refuses to every other format OpenImageIO has (video and
// camera-raw decoders among them), each a parser of hostile bytes and some slow to give up.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <memory>
#include <string_view>

namespace glossy {

// The open reader, its spec checked to be a 2D image with pixels and channels. Throws InputError "PATH: ..."
// naming `kind` ("image", "sheet", "PNG") otherwise.
std::unique_ptr<OIIO::ImageInput> openImageFile(const std::filesystem::path& path, std::string_view kind);

}  // namespace glossy
