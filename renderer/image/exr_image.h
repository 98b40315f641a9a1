// Linear RGB images and their EXR files: written atomically (a temporary beside the target, renamed into
// place), with the glossy:* metadata of shared/spec/interfaces.md.
#pragma once

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace glossy {

struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> pixels;  // RGB interleaved, row 0 at the top

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), pixels(size_t(w) * size_t(h) * 3, 0.0f) {}
  float* at(int x, int y) { return &pixels[(size_t(y) * size_t(width) + size_t(x)) * 3]; }
  const float* at(int x, int y) const { return &pixels[(size_t(y) * size_t(width) + size_t(x)) * 3]; }
};

struct ImageAttribute {
  std::string name;
  std::variant<std::string, int, float> value;
};

enum class PixelType { Half, Float };

// The largest finite half-float.
inline constexpr float kLargestHalf = 65504.0f;

// Throws std::runtime_error naming the path on failure; the temporary is removed, the target untouched.
// Writes no Inf or NaN: values beyond the pixel type's largest finite one are clamped to it, NaN written as
// 0, and the pixels so changed counted in the metadata: glossy:halfClampedPixels (always, for half),
// glossy:nonFinitePixels (for float, when any).
void writeExr(const std::filesystem::path& path, const RgbImage& image, const std::vector<ImageAttribute>& attributes,
              PixelType type = PixelType::Float);

// An EXR with named layers, written as channels PREFIX.R/G/B (an empty prefix gives the default R, G, B
// layer), or PREFIX.Y for a greyscale layer (the image's first channel). The file is as large as the first
// layer; a smaller layer sits with its left column at x and its top at row 0, black elsewhere, so a sheet's
// panels each fill their own box without a grid-sized copy each. Atomic like writeExr.
struct ExrLayer {
  std::string prefix;
  const RgbImage* image;
  int x = 0;
  bool greyscale = false;
};
void writeLayeredExr(const std::filesystem::path& path, const std::vector<ExrLayer>& layers,
                     const std::vector<ImageAttribute>& attributes, PixelType type = PixelType::Float);

// An 8-bit image (PNG by the extension) from interleaved RGB bytes, written atomically.
void writeRgb8(const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgb);

// Reads the first three channels of any image OpenImageIO reads; throws InputError naming the file.
RgbImage readRgbImage(const std::filesystem::path& path);
// The string value of a metadata attribute of an image file ("" if absent).
std::string readImageAttribute(const std::filesystem::path& path, const std::string& name);
// One named layer (channels PREFIX.R/G/B) of an image file; throws InputError naming the file and layer.
RgbImage readImageLayer(const std::filesystem::path& path, const std::string& prefix);

}  // namespace glossy
