// Emissive triangles (glTF emissiveFactor) as area lights, sampled uniformly by area. Emission is
// one-sided: from the side the triangle's winding faces, as glTF's single-sided materials imply.
#pragma once

#include "renderer/scene/scene.h"

#include <vector>

namespace glossy {

class AreaLights {
 public:
  struct Sample {
    Vec3 position{0.0}, normal{0.0};
    Rgb radiance{0.0};
    double pdfArea = 0.0;  // 0 = invalid
  };

  explicit AreaLights(const SceneDescription& scene);
  bool empty() const { return triangles_.empty(); }
  double totalArea() const { return totalArea_; }
  Sample sample(double uTriangle, Vec2 u) const;
  // Density of sample() at a point of an emissive triangle, per unit area.
  double pdfArea() const { return empty() ? 0.0 : 1.0 / totalArea_; }

 private:
  struct Triangle {
    Vec3 p0, e1, e2, normal;
    Rgb radiance;
  };
  std::vector<Triangle> triangles_;
  std::vector<double> cdf_;  // cumulative area, last = totalArea_
  double totalArea_ = 0.0;
};

}  // namespace glossy
