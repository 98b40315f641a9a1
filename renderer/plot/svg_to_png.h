// PNGs of the figures, rendered from their SVG by rsvg-convert (Debian's librsvg2-bin) rather than by a
// second drawing path of our own, so the PNG is the SVG, pixel for pixel what a browser shows.
#pragma once

#include <filesystem>
#include <optional>

namespace glossy::plot {

// rsvg-convert on $PATH, or nullopt.
std::optional<std::filesystem::path> findRsvgConvert();

// Renders `svg` (a file) to `png` at `zoom` × its size on a white background, atomically (a temporary
// beside `png`, renamed into place). Throws std::runtime_error naming the file when rsvg-convert fails.
void svgToPng(const std::filesystem::path& rsvgConvert, const std::filesystem::path& svg, const std::filesystem::path& png,
              double zoom);

}  // namespace glossy::plot
