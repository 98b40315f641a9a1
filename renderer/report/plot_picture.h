// A plot's picture as the site shows it. The page's figure grid shows each plot about 340 to 460 CSS pixels
// wide, while glossy plot's PNGs are 1,300 to 1,700 pixels wide (1.5 pixels per SVG unit, for print): the
// site scales each to at most kSitePictureWidth pixels, sharp at 2 device pixels per CSS pixel, and keeps
// it as WebP at quality 90 — about a sixth of the PNG, text and lines still clean. The figure's exact form
// is its SVG (copied with --plot-data). Where OpenImageIO cannot write WebP, the scaled picture is a PNG.
#pragma once

#include <filesystem>
#include <set>
#include <string>

namespace glossy::report {

inline constexpr int kSitePictureWidth = 960;

// Checks the picture's header before any writing: InputError naming it unless it is an image OpenImageIO
// reads, with 1 to 4 channels and a size the report handles.
void checkPlotPicture(const std::filesystem::path& file);

// The site's name for the picture `png` ("theta_h.png" -> "theta_h.webp"), one not in `taken` (the other
// files of the same plots).
std::string sitePictureName(const std::string& png, const std::set<std::string>& taken);

// Reads `from`, scales it to at most kSitePictureWidth wide and writes it to `to` (WebP, or PNG when the
// name says so) atomically. InputError naming `from` when its pixels cannot be read.
void writeSitePicture(const std::filesystem::path& from, const std::filesystem::path& to);

}  // namespace glossy::report
