// Distant lighting from a lat-long (equirectangular) map or a constant, with importance sampling.
// Direction convention (shared/spec/interfaces.md, = Mitsuba 3's envmap with identity transform):
// world direction d (Y up) ↦ u = atan2(d_x, −d_z)/(2π) wrapped to [0,1), v = acos(d_y)/π (v = 0 top row).
// Lookup is bilinear with columns at texel centres (x = u·W − ½, wrapping) and rows spanning pole to pole
// (y = v·(H − 1), row 0 exactly +Y). --env-rotate rotates the map about +Y.
#pragma once

#include "materials/core/types.h"
#include "renderer/lights/latlong.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

namespace glossy {

class Environment {
 public:
  // No member initialisers: a batch's array of them is filled lane by lane, never cleared ({} zeroes one).
  struct Sample {
    Vec3 dir;  // world direction toward the light (away from the scene)
    Rgb radiance;
    double pdf;  // solid angle; 0 = invalid
  };

  // The largest map: at most 2^28 texels (16384 × 16384, or 32768 × 8192: gigabytes, at what a texel costs
  // with its sampling tables, docs/performance.md), and at most 65536 on a side (OpenImageIO's reading buffer holds whole rows). Checked on the
  // header, before anything is allocated, so that a file claiming more (which a few bytes of header can)
  // is refused as bad input instead of exhausting memory.
  static constexpr std::int64_t kMaxTexels = std::int64_t(1) << 28;
  static constexpr int kMaxSide = 65536;

  // .exr or .hdr via OpenImageIO. Throws InputError naming the file (unreadable, not RGB(A), larger than
  // the limits above or the memory here, non-finite or negative texels). rotateDegrees rotates the map
  // about +Y (right-handed): a positive angle turns its features counter-clockwise seen from above, +Z
  // towards +X (90° moves what was at +X to −Z).
  static Environment load(const std::filesystem::path& path, double rotateDegrees = 0.0);
  static Environment constant(const Rgb& radiance);
  // A procedural sky the project makes itself: soft gradient sky, a bright sun-like key, a darker ground.
  static Environment makeDefault(double rotateDegrees = 0.0);

  Rgb radiance(const Vec3& dir) const;     // radiance arriving from direction dir
  // Directions toward a surface of the given normal (unit, world space), importance-sampled by the map's
  // luminance × sin θ within each cell of the map and by the cells' light × the largest cos θ the normal's
  // bin can make with them (cosine_bins.h); the constant environment cosine-weighted about the normal.
  // The zero normal: no surface, the map's luminance alone (the constant environment uniform).
  Sample sample(const Vec3& normal, Vec2 u) const;
  double pdf(const Vec3& normal, const Vec3& dir) const;  // exactly the density sample(normal, ·) draws from
  // Both at once, from one direction-to-map conversion (the path tracer's escaping rays need both).
  Rgb radianceAndPdf(const Vec3& normal, const Vec3& dir, double& pdf) const;
  // Batch forms for the path tracer's waves: for the lanes with want[i] (i < n ≤ kMaxBatch), exactly
  // what sample(normals[i], u[i]) and radianceAndPdf(normals[i], dirs[i], pdf[i]) return. The lanes' map
  // lines are prefetched together before any is read, so that their cache misses overlap instead of queueing.
  static constexpr int kMaxBatch = 128;
  void sample(const bool* want, const Vec3* normals, const Vec2* u, Sample* out, int n) const;
  void radianceAndPdf(const bool* want, const Vec3* normals, const Vec3* dirs, Rgb* radiance, double* pdf, int n) const;
  double meanLuminance() const;  // over the sphere of directions
  const std::string& description() const;  // for image metadata: file name, "constant r,g,b", "default sky"

  Environment(Environment&&) noexcept;
  Environment& operator=(Environment&&) noexcept;
  ~Environment();

 private:
  struct Impl;
  explicit Environment(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace glossy
