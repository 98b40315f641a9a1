// Colours for pictures of numbers: the sRGB transfer function, and the colour maps every figure shares —
// the sheets' error rows, the report, and glossy plot — so a colour means the same everywhere.
// Maps return display (sRGB-encoded) values in [0, 1]; inputs outside the range are clamped, NaN is the
// range's middle (diverging) or its bottom (sequential).
#pragma once

#include <array>
#include <string>

namespace glossy {

using DisplayColour = std::array<float, 3>;

// sRGB transfer function (IEC 61966-2-1) of a linear value, clamped to [0, 1]; NaN is black.
float srgbEncode(double linear);

// t in [−1, 1]: blue (−1) … white (0) … red (+1), ColorBrewer's RdBu: for signed differences and log-ratios.
DisplayColour divergingColour(double t);
// t in [0, 1]: dark blue … green … yellow (viridis), for magnitudes (a BRDF's image slice).
DisplayColour viridisColour(double t);

// "#rrggbb" of a display colour.
std::string hexColour(const DisplayColour& c);

}  // namespace glossy
