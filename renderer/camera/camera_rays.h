// Primary rays of a glTF camera. The camera looks down its −Z axis with +Y up; image row 0 is the top.
// Perspective: yfov is vertical, and the horizontal extent follows the image's aspect ratio (glTF's
// aspectRatio is a hint; the image size decides). Orthographic: xmag, ymag are the view's half extents.
#pragma once

#include "renderer/scene/embree_scene.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>

namespace glossy {

// `film` is the position on the image in pixels: (0,0) its top-left corner, (width, height) bottom-right.
inline Ray cameraRay(const Camera& camera, int width, int height, Vec2 film) {
  const double sx = 2.0 * film.x / width - 1.0;   // −1 left … +1 right
  const double sy = 1.0 - 2.0 * film.y / height;  // +1 top … −1 bottom
  Ray ray;
  if (camera.type == Camera::Type::Perspective) {
    const double ty = std::tan(0.5 * camera.yfov), tx = ty * double(width) / double(height);
    const glm::dvec4 d = camera.cameraToWorld * glm::dvec4(sx * tx, sy * ty, -1.0, 0.0);
    ray.origin = Vec3(camera.cameraToWorld[3]);
    ray.dir = glm::normalize(Vec3(d));
  } else {
    const glm::dvec4 o = camera.cameraToWorld * glm::dvec4(sx * camera.xmag, sy * camera.ymag, 0.0, 1.0);
    ray.origin = Vec3(o);
    ray.dir = glm::normalize(Vec3(camera.cameraToWorld * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
  }
  return ray;
}

}  // namespace glossy
