#include "tests/support/render_fixtures.h"

#include "renderer/image/exr_image.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace glossy::test {

Mesh quad(glm::vec3 corner, glm::vec3 edgeU, glm::vec3 edgeV, int material) {
  Mesh m;
  m.name = "test quad";
  m.material = material;
  m.positions = {corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

double projectedSolidAngle(const glm::dvec3 (&corners)[4], const glm::dvec3& p) {
  double e = 0.0;
  for (int i = 0; i < 4; ++i) {
    const glm::dvec3 a = glm::normalize(corners[i] - p), b = glm::normalize(corners[(i + 1) % 4] - p);
    e += std::acos(glm::dot(a, b)) * glm::normalize(glm::cross(a, b)).y;
  }
  return 0.5 * std::abs(e);
}

void writePanelsMap(const std::filesystem::path& path, int width, int height) {
  RgbImage map(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const double sky = 0.05 + 0.15 * double(y) / (height - 1);
      for (int c = 0; c < 3; ++c) map.at(x, y)[c] = float(sky * (1.0 + 0.2 * c));
    }
  const auto panel = [&](int x, int y, Rgb radiance) {
    for (int c = 0; c < 3; ++c) map.at(x, y)[c] = float(radiance[c]);
  };
  panel(width / 8, height / 4, Rgb(400.0, 300.0, 200.0));
  panel(width / 2, height / 3, Rgb(100.0, 200.0, 400.0));
  panel(3 * width / 4, 2 * height / 3, Rgb(300.0, 300.0, 300.0));
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) panel(width / 3 + dx, height / 5 + dy, Rgb(50.0, 60.0, 70.0));
  panel(width / 5, 0, Rgb(80.0, 80.0, 80.0));
  writeExr(path, map, {});
}

SceneMaterial material(const char* name, Rgb baseColor, Rgb emission) {
  SceneMaterial m;
  m.name = name;
  m.baseColor = baseColor;
  m.emission = emission;
  return m;
}

Mesh uvSphere(double radius, int segments, int rings, int material) {
  Mesh m;
  m.name = "test sphere";
  m.material = material;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s <= segments; ++s) {
      const double theta = kPi * r / rings, phi = 2 * kPi * s / segments;
      const glm::vec3 n(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)), float(std::sin(theta) * std::sin(phi)));
      m.positions.push_back(n * float(radius));
      m.normals.push_back(n);
    }
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments + 1);
      // Counter-clockwise seen from outside.
      m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  return m;
}

Camera orthographicDown(double halfExtent, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up) {
  Camera c;
  c.type = Camera::Type::Orthographic;
  c.cameraToWorld = glm::inverse(glm::lookAt(eye, target, up));
  c.xmag = c.ymag = halfExtent;
  return c;
}

Rgb directionalAlbedo(const Brdf& brdf, const Vec3& V, int nMu, int nPhi) {
  Rgb sum(0.0);
  for (int i = 0; i < nMu; ++i) {
    const double mu = (i + 0.5) / nMu, st = std::sqrt(1 - mu * mu);
    for (int j = 0; j < nPhi; ++j) {
      const double phi = 2 * kPi * (j + 0.5) / nPhi;
      sum += eval(brdf, Vec3(st * std::cos(phi), st * std::sin(phi), mu), V) * mu;
    }
  }
  return sum * (2 * kPi / (double(nMu) * nPhi));
}

Camera perspective(glm::dvec3 eye, glm::dvec3 target, double yfov) {
  Camera c;
  c.cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::dvec3(0, 1, 0)));
  c.yfov = yfov;
  return c;
}

SphereOnFloor::SphereOnFloor(const Brdf& sphere, bool lamp) {
  description.materials = {material("sphere"), material("floor"), material("lamp", Rgb(0.0), Rgb(4.0, 3.0, 2.0))};
  description.meshes.push_back(uvSphere(1.0, 64, 32, 0));
  description.meshes.push_back(quad({-4, -1, 4}, {8, 0, 0}, {0, 0, -8}, 1));
  if (lamp) description.meshes.push_back(quad({-1, 2.5f, -1}, {2, 0, 0}, {0, 0, 2}, 2));
  brdfs = {sphere, Lambertian{Rgb(0.6, 0.5, 0.4)}, Lambertian{Rgb(0.0)}};
}

}  // namespace glossy::test
