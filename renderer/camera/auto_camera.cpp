#include "renderer/camera/auto_camera.h"

#include "materials/core/input_error.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

namespace {

// scenes/preview.gltf's camera: its rotation (a turn about +X, glTF's x, y, z, w order) and yfov.
constexpr double kPreviewRotationX = -0.06311208592535798, kPreviewRotationW = 0.9980064451746543;
constexpr double kPreviewYfov = 0.5235987755982988;

bool isBound(const SceneDescription& scene, const Mesh& mesh) {
  return mesh.material >= 0 && !scene.materials[size_t(mesh.material)].glossyMaterial.empty();
}

}  // namespace

Camera autoCamera(const SceneDescription& scene, double aspect) {
  const bool anyBound = std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& m) { return isBound(scene, m); });
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const Mesh& m : scene.meshes)
    if (!anyBound || isBound(scene, m))
      for (const glm::vec3& p : m.positions) {
        lo = glm::min(lo, glm::dvec3(p));
        hi = glm::max(hi, glm::dvec3(p));
      }
  if (!(lo.x <= hi.x)) throw InputError(scene.source.string() + ": the scene has no geometry to frame");
  const glm::dvec3 centre = 0.5 * (lo + hi);
  double radius = 0.0;
  for (const Mesh& m : scene.meshes)
    if (!anyBound || isBound(scene, m))
      for (const glm::vec3& p : m.positions) radius = std::max(radius, glm::length(glm::dvec3(p) - centre));

  const double tanHalfY = std::tan(0.5 * kPreviewYfov);
  const double tanHalf = std::min(tanHalfY, tanHalfY * (aspect > 0.0 ? aspect : 1.0));
  // The sphere touches the frame's narrower sides when its tangent cone's half-angle is the view's.
  const double distance = radius / std::sin(std::atan(tanHalf));
  const glm::dquat q(kPreviewRotationW, kPreviewRotationX, 0.0, 0.0);
  const glm::dmat4 rotation = glm::mat4_cast(glm::normalize(q));
  const glm::dvec3 forward(rotation * glm::dvec4(0.0, 0.0, -1.0, 0.0));
  const glm::dvec3 position = centre - distance * forward;
  if (!(std::max({std::abs(position.x), std::abs(position.y), std::abs(position.z)}) <= kMaxSceneCoordinate))
    throw InputError(scene.source.string() + ": the scene is too large to frame with an automatic camera");

  Camera camera;
  camera.name = "auto";
  camera.type = Camera::Type::Perspective;
  camera.yfov = kPreviewYfov;
  camera.aspectRatio = 0.0;
  camera.cameraToWorld = glm::translate(glm::dmat4(1.0), position) * rotation;
  return camera;
}

}  // namespace glossy
