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

// Throws std::runtime_error naming the path on failure; the temporary is removed, the target untouched.
void writeExr(const std::filesystem::path& path, const RgbImage& image, const std::vector<ImageAttribute>& attributes,
              PixelType type = PixelType::Float);

// Reads the first three channels of any image OpenImageIO reads; throws InputError naming the file.
RgbImage readRgbImage(const std::filesystem::path& path);
// The string value of a metadata attribute of an image file ("" if absent).
std::string readImageAttribute(const std::filesystem::path& path, const std::string& name);

}  // namespace glossy
