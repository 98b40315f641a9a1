// The scene's triangles in an Embree 3 BVH: closest-hit and occlusion queries.
#pragma once

#include "renderer/scene/scene.h"

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace glossy {

struct Ray {
  Vec3 origin;
  Vec3 dir;  // unit
  double tnear = 0.0;
  double tfar = 1e30;
};

struct Hit {
  double t = 0.0;
  uint32_t mesh = 0;      // index into SceneDescription::meshes
  uint32_t triangle = 0;
  double u = 0.0, v = 0.0;  // barycentrics of vertices 1 and 2
  Vec3 position{0.0};
  Vec3 geometricNormal{0.0};  // unit, as wound (not flipped toward the ray)
  Vec3 shadingNormal{0.0};    // unit, interpolated vertex normals, or the geometric normal
  // How far a ray leaving this point must start off the surface (spawnRay) so that Embree, which tests
  // in float, cannot find this triangle again: a bound on float rounding at the triangle's magnitude.
  double margin = 0.0;
};

// Two-sided shading: a hit's geometric and shading normals turned toward the viewer (wo, unit, from the hit
// toward where the ray came from). A shading normal that still faces away would let light through the
// surface, so the geometric one stands in for it there.
inline void normalsFacing(const Hit& hit, const Vec3& wo, Vec3& ng, Vec3& ns) {
  ng = hit.geometricNormal, ns = hit.shadingNormal;
  if (glm::dot(wo, ng) < 0.0) ng = -ng, ns = -ns;
  if (glm::dot(wo, ns) <= 0.0) ns = ng;
}

// The margin of a surface whose coordinates reach maxAbs: 2⁻¹⁹ of it, 16 to 32 float ulps of it. The origin's rounding to
// float (½ ulp a coordinate) and Embree's float plane test (a few ulps of the vertices' magnitude) stay
// below it, and it scales with the scene, so a scene and its copy scaled by 1e3 render alike.
inline double surfaceMargin(double maxAbs) { return 0x1p-19 * maxAbs; }
inline double maxAbsComponent(const Vec3& p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }
inline double triangleMargin(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
  return surfaceMargin(std::max({maxAbsComponent(p0), maxAbsComponent(p1), maxAbsComponent(p2)}));
}

// A ray leaving a surface point with margin m and geometric normal ng, in unit direction dir: it starts m
// off the surface on dir's side.
inline Ray spawnRay(const Vec3& p, const Vec3& ng, double margin, const Vec3& dir) {
  return Ray{p + ng * (glm::dot(dir, ng) > 0.0 ? margin : -margin), dir, 0.0, 1e30};
}

// The Embree form of a ray (float; tfar beyond float range becomes +∞).
RTCRay toRtcRay(const Ray& ray);

// Writes one ray into lane `lane` of an Embree SoA packet.
inline void setPacketLane(RTCRay8& packet, int lane, const RTCRay& r) {
  packet.org_x[lane] = r.org_x;
  packet.org_y[lane] = r.org_y;
  packet.org_z[lane] = r.org_z;
  packet.tnear[lane] = r.tnear;
  packet.dir_x[lane] = r.dir_x;
  packet.dir_y[lane] = r.dir_y;
  packet.dir_z[lane] = r.dir_z;
  packet.time[lane] = r.time;
  packet.tfar[lane] = r.tfar;
  packet.mask[lane] = r.mask;
  packet.id[lane] = r.id;
  packet.flags[lane] = r.flags;
}

// Lane `lane` of a closest-hit packet and its mask: the ray, or (ray == nullptr) an inactive lane. Either
// way the hit starts as "none", which Embree leaves in place for a miss.
inline void setPacketHitLane(RTCRayHit8& packet, int* mask, int lane, const RTCRay* ray) {
  mask[lane] = ray ? -1 : 0;
  packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
  packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
  if (ray) setPacketLane(packet.ray, lane, *ray);
}

// Lanes of a packet query: Embree's native 8-wide packets (AVX2), which trace coherent rays (a pixel's
// samples, their glossy reflections, their shadow rays toward the same light) faster than one at a time.
inline constexpr int kPacketSize = 8;

// Sees every query an EmbreeScene answers; the benchmark uses it to replay the renderer's exact ray
// distribution through raw Embree. Must be thread-safe.
class RayRecorder {
 public:
  virtual ~RayRecorder() = default;
  virtual void record(const Ray& ray, bool shadow) = 0;
  // A packet query: the rays of the lanes with valid[i], as one call.
  virtual void recordPacket(const Ray* rays, const bool* valid, bool shadow) = 0;
};

class EmbreeScene {
 public:
  explicit EmbreeScene(const SceneDescription& scene);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  bool intersect(const Ray& ray, Hit& hit) const;  // closest hit within [tnear, tfar]
  bool occluded(const Ray& ray) const;             // any hit within [tnear, tfar]
  // The same for n rays at once (n a multiple of kPacketSize), traced as Embree packets of kPacketSize;
  // rays with valid[i] false are neither traced nor written.
  void intersect(const bool* valid, const Ray* rays, Hit* hits, bool* found, int n) const;
  void occluded(const bool* valid, const Ray* rays, bool* occluded, int n) const;
  // A sphere around all geometry, centred on its bounding box (not the smallest one): for the environment
  // light's power and default cameras.
  Vec3 boundsCenter() const { return center_; }
  double boundsRadius() const { return radius_; }

  void setRecorder(RayRecorder* recorder) { recorder_ = recorder; }  // nullptr (default): none
  RTCScene handle() const { return rtcScene_; }                      // for raw-Embree benchmarks

 private:
  void throwIfEmbreeFailed(const char* doing) const;
  // The hit on primitive `triangle` of mesh `mesh` that Embree found at (t, u, v), in double from the mesh:
  // the same hit whether Embree answered a one-ray or a packet query.
  Hit completeHit(const Ray& ray, uint32_t mesh, uint32_t triangle, double t, double u, double v) const;
  void release();
  // One packet of kPacketSize rays.
  void intersectPacket(const bool* valid, const Ray* rays, Hit* hits, bool* found) const;
  void occludedPacket(const bool* valid, const Ray* rays, bool* occluded) const;

  const SceneDescription& scene_;
  std::string embreeError_;  // set by Embree's error callback, turned into an exception by throwIfEmbreeFailed
  RTCDevice device_ = nullptr;
  RTCScene rtcScene_ = nullptr;
  Vec3 center_{0.0};
  double radius_ = 0.0;
  RayRecorder* recorder_ = nullptr;
};

}  // namespace glossy
