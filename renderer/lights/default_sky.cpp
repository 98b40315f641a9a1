// The procedural default sky: each texel is the radiance of a small analytic studio scene seen in that
// texel's direction.
#include "renderer/lights/default_sky.h"

#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace glossy {

namespace {

constexpr int kWidth = 1024, kHeight = 512;

double smoothstep(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double degrees(double radians) { return radians * (180.0 * kInvPi); }

// Direction at azimuth `u` (the map's u, as a fraction of a turn) and elevation above the horizon.
Vec3 towards(double u, double elevationDegrees) {
  return directionFromLatLong({u, 0.5 - elevationDegrees / 180.0});
}

// 1 inside an azimuth × elevation rectangle, falling smoothly to 0 over `soft` degrees across each edge.
// Soft edges keep highlights on polished materials free of aliasing and keep the sampling pdf smooth.
double softRectangle(double azimuth, double elevation, double azimuthCentre, double azimuthHalfWidth,
                     double elevationLow, double elevationHigh, double soft) {
  const double dAzimuth = std::abs(std::remainder(azimuth - azimuthCentre, 360.0));
  const double across = 1.0 - smoothstep(azimuthHalfWidth - soft, azimuthHalfWidth + soft, dAzimuth);
  const double up = smoothstep(elevationLow - soft, elevationLow + soft, elevation) *
                    (1.0 - smoothstep(elevationHigh - soft, elevationHigh + soft, elevation));
  return across * up;
}

// The key light sits at the camera's front right (a camera on +Z looking at the origin sees it from
// upper right), the fill on the opposite side, the rim behind the subject.
const Vec3 kSunDirection = towards(0.375, 45.0);
const Rgb kSunRadiance{95.0, 84.0, 68.0};  // warm white; ≈0.4 of the sky+sun irradiance on a facing surface
constexpr double kSunCoreDegrees = 2.5, kSunEdgeDegrees = 4.5;  // ≈ 7° across at half brightness

const Rgb kZenith{0.22, 0.30, 0.46};
const Rgb kHorizon{0.52, 0.55, 0.60};
const Rgb kGround{0.10, 0.095, 0.09};

Rgb radianceToward(const Vec3& d) {
  const double elevation = degrees(std::asin(std::clamp(d.y, -1.0, 1.0)));
  const double azimuth = 360.0 * latLongFromDirection(d).x;

  // Sky brightens towards the horizon; the ground is neutral and meets it over a couple of degrees.
  const Rgb sky = glm::mix(kHorizon, kZenith, std::sqrt(std::max(d.y, 0.0)));
  Rgb radiance = glm::mix(kGround, sky, smoothstep(-2.0, 2.0, elevation));

  const double sunAngle = degrees(std::acos(std::clamp(glm::dot(d, kSunDirection), -1.0, 1.0)));
  radiance += kSunRadiance * (1.0 - smoothstep(kSunCoreDegrees, kSunEdgeDegrees, sunAngle));
  // A faint aureole so the sun reads as a light in the sky, not a disc pasted on it.
  radiance += Rgb(0.9, 0.75, 0.55) * std::exp(-sunAngle / 8.0);

  const double fill = softRectangle(azimuth, elevation, 240.0, 14.0, 8.0, 38.0, 2.0);
  const double rim = softRectangle(azimuth, elevation, 10.0, 5.0, 15.0, 60.0, 1.5);
  radiance += fill * Rgb(2.4, 2.45, 2.55) + rim * Rgb(3.0, 3.1, 3.3);
  return radiance;
}

}  // namespace

LatLongImage makeDefaultSky() {
  LatLongImage image(kWidth, kHeight);
  for (int row = 0; row < kHeight; ++row)
    for (int column = 0; column < kWidth; ++column) {
      const Rgb value = radianceToward(directionFromLatLong(image.texelUv(column, row)));
      for (int c = 0; c < 3; ++c) image.at(column, row)[c] = float(value[c]);
    }
  return image;
}

}  // namespace glossy
