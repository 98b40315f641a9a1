// Basic value types shared by the whole project. BRDFs are evaluated in double: the published fits
// (AS n up to 6.2e5, ABC B up to 8.1e6) lose their peaks in float.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <numbers>

namespace glossy {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Rgb = glm::dvec3;

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = std::numbers::inv_pi;

// Relative luminance of linear Rec. 709 RGB.
inline double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

}  // namespace glossy
