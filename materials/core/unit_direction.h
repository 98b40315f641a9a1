// A direction given by a user (a line of `glossy eval`, a row of a NumPy array) as the unit vector the
// models take. A vector whose squared length is 1 to within a few ulps is taken as it is: dividing it by
// its length would only round it again (a normalised vector is no closer to unit length than that), and
// inputs are mostly unit vectors already, which then cost no square root and no divisions.
#pragma once

#include "materials/core/types.h"

#include <cmath>
#include <limits>

namespace glossy {

// How far from 1 the squared length of a vector taken as unit may be: four ulps of 1.
inline constexpr double kUnitSquaredLength = 0x1p-50;

// d is taken as a unit vector as it is.
inline bool isUnitDirection(const Vec3& d) {
  return std::abs(d.x * d.x + d.y * d.y + d.z * d.z - 1.0) <= kUnitSquaredLength;  // false for NaN
}

// d as a unit vector, in place; false for a zero or non-finite d.
inline bool makeUnitDirection(Vec3& d) {
  if (isUnitDirection(d)) return true;
  const double squared = d.x * d.x + d.y * d.y + d.z * d.z;
  const double length = std::sqrt(squared);
  if (!(length > 0.0 && length <= std::numeric_limits<double>::max())) return false;
  d /= length;
  return true;
}

}  // namespace glossy
