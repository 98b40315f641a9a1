// Primary rays of a glTF camera. The camera looks down its −Z axis with +Y up; image row 0 is the top.
// Perspective: yfov is vertical, and the horizontal extent follows the image's aspect ratio (glTF's
// aspectRatio is a hint; the image size decides). Orthographic: xmag, ymag are the view's half extents.
#pragma once

#include "renderer/scene/embree_scene.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

// `film` is the position on the image in pixels: (0,0) its top-left corner, (width, height) bottom-right.
// Everything that does not depend on the film position is computed once, so a ray costs a matrix-vector
// product and a normalisation.
class CameraRays {
 public:
  CameraRays(const Camera& camera, int width, int height)
      : perspective_(camera.type == Camera::Type::Perspective), cameraToWorld_(camera.cameraToWorld),
        width_(width), height_(height) {
    if (perspective_) {
      // Only the axes' directions matter to a perspective camera: a node scaled by 1e-200 or 1e200 (checked
      // non-singular by the loader) is brought to unit scale by a power of two, which leaves the normalised
      // directions bit for bit what they were and keeps them from underflowing or overflowing.
      double scale = 0.0;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) scale = std::max(scale, std::abs(cameraToWorld_[i][j]));
      if (scale > 0.0 && std::isfinite(scale))
        for (int i = 0; i < 3; ++i) cameraToWorld_[i] = std::ldexp(1.0, -std::ilogb(scale)) * cameraToWorld_[i];
      halfExtent_.y = std::tan(0.5 * camera.yfov);
      halfExtent_.x = halfExtent_.y * double(width) / double(height);
      origin_ = Vec3(camera.cameraToWorld[3]);
    } else {
      halfExtent_ = {camera.xmag, camera.ymag};
    }
    forward_ = glm::normalize(Vec3(camera.cameraToWorld * glm::dvec4(0.0, 0.0, -1.0, 0.0)));
  }

  Ray operator()(Vec2 film) const {
    const double sx = (2.0 * film.x / width_ - 1.0) * halfExtent_.x;   // −1 left … +1 right
    const double sy = (1.0 - 2.0 * film.y / height_) * halfExtent_.y;  // +1 top … −1 bottom
    Ray ray;
    if (perspective_) {
      ray.origin = origin_;
      ray.dir = glm::normalize(Vec3(cameraToWorld_ * glm::dvec4(sx, sy, -1.0, 0.0)));
    } else {
      ray.origin = Vec3(cameraToWorld_ * glm::dvec4(sx, sy, 0.0, 1.0));
      ray.dir = forward_;
    }
    return ray;
  }

 private:
  bool perspective_;
  glm::dmat4 cameraToWorld_;
  int width_, height_;
  Vec2 halfExtent_{0.0};
  Vec3 origin_{0.0}, forward_{0.0};
};

inline Ray cameraRay(const Camera& camera, int width, int height, Vec2 film) {
  return CameraRays(camera, width, height)(film);
}

}  // namespace glossy
