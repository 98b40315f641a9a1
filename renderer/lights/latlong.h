// The lat-long (equirectangular) parameterisation of directions and a bilinearly looked-up RGB map on it,
// with the spec's conventions (shared/spec/interfaces.md, = Mitsuba 3's envmap with identity transform):
// u = atan2(d_x, −d_z)/(2π) wrapped to [0,1), v = acos(d_y)/π; columns sit at texel centres
// (x = u·W − ½, wrapping), rows span pole to pole (y = v·(H − 1), row 0 exactly +Y).
#pragma once

#include "materials/core/types.h"
#include "materials/sampling/huge_pages.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace glossy {

// x − ⌊x⌋, but never 1.0 (which a tiny negative x would round to).
inline double wrapUnit(double x) {
  const double w = x - std::floor(x);
  return w < 1.0 ? w : 0.0;
}

// (u, v) of a unit direction.
inline Vec2 latLongFromDirection(const Vec3& d) {
  const double u = wrapUnit(std::atan2(d.x, -d.z) * (0.5 * kInvPi));
  const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) * kInvPi;
  return {u, v};
}

inline Vec3 directionFromLatLong(Vec2 uv) {
  const double theta = kPi * uv.y, phi = 2.0 * kPi * uv.x;
  const double sinTheta = std::sin(theta);
  return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

// Linear RGB texels, row-major from the top (+Y) row, 3 floats per texel: float halves the memory of a
// 4k map and is all that .hdr/.exr files hold anyway.
struct LatLongImage {
  int width = 0;
  int height = 0;  // at least 2: rows are interpolated pole to pole
  std::vector<float> rgb;

  Rgb texel(int column, int row) const {
    const float* t = &rgb[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * 3];
    return {t[0], t[1], t[2]};
  }

  // The centre of column i and row j in (u, v): where the map's value is exactly texel(i, j).
  Vec2 texelUv(int column, int row) const {
    return {(column + 0.5) / width, double(row) / double(height - 1)};
  }
};

// Where a bilinear lookup at (u, v) falls: columns c0, c1 = c0 + 1 (wrapping) and rows r0, r0 + 1, with
// the weights fx, fy of the second of each. A plain aggregate, always built whole: the batch lookups keep
// arrays of them that are not zeroed per call.
struct LatLongPosition {
  int c0, c1, r0;
  double fx, fy;
};

inline LatLongPosition latLongPosition(Vec2 uv, int width, int height) {
  const double x = uv.x * width - 0.5;
  const double x0 = std::floor(x);
  int c0 = int(x0) % width;
  if (c0 < 0) c0 += width;
  const double y = std::clamp(uv.y, 0.0, 1.0) * (height - 1);
  const int r0 = std::min(int(y), height - 2);
  return {c0, c0 + 1 == width ? 0 : c0 + 1, r0, x - x0, y - r0};
}

// A LatLongImage's texels in huge pages (huge_pages.h), for the environment light's random lookups, and
// its bilinear interpolation at a lookup position.
class LatLongMap {
 public:
  LatLongMap() = default;
  explicit LatLongMap(const LatLongImage& image)
      : width_(image.width), height_(image.height), rgb_(image.rgb.begin(), image.rgb.end()) {}

  int width() const { return width_; }
  int height() const { return height_; }

  Rgb interpolate(const LatLongPosition& p) const {
    const auto rgb = [&](int column, int row) {
      const float* t = at(column, row);
      return Rgb(t[0], t[1], t[2]);
    };
    const Rgb top = rgb(p.c0, p.r0) * (1.0 - p.fx) + rgb(p.c1, p.r0) * p.fx;
    const Rgb bottom = rgb(p.c0, p.r0 + 1) * (1.0 - p.fx) + rgb(p.c1, p.r0 + 1) * p.fx;
    return top * (1.0 - p.fy) + bottom * p.fy;
  }
  // The texels interpolate(p) will read: a row's two texels are 24 bytes and may straddle a cache line,
  // so both ends are fetched.
  void prefetch(const LatLongPosition& p) const {
    __builtin_prefetch(at(p.c0, p.r0));
    __builtin_prefetch(at(p.c1, p.r0) + 2);
    __builtin_prefetch(at(p.c0, p.r0 + 1));
    __builtin_prefetch(at(p.c1, p.r0 + 1) + 2);
  }

 private:
  const float* at(int column, int row) const {
    return &rgb_[(std::size_t(row) * std::size_t(width_) + std::size_t(column)) * 3];
  }
  int width_ = 0, height_ = 0;
  HugePageVector<float> rgb_;
};

// The cells of a W × H lat-long map (the bilinear patches between texel centres, W × (H − 1)) as
// directions, without atan2, acos, sin or cos per call: between the cell edges, whose sines and cosines are
// tabulated, the angles are within one cell of an edge, where short series are exact to double rounding.
// A map is turned by uOffset (looked up at u_world + uOffset).
//
// position() gives what latLongPosition(u, v) gives for the direction's (u, v) — the same cell and the
// same weights up to rounding (a few 1e-16) — and direction() is its inverse. Maps too coarse for the
// series (cells wider than kMaxStep) take the libm formulas.
class LatLongGrid {
 public:
  static constexpr double kMaxStep = 0.025;  // radians; the series below are exact to ~1e-19 up to here

  LatLongGrid() = default;
  LatLongGrid(int width, int height, double uOffset)
      : width_(width), height_(height), uOffset_(uOffset), rows_(height - 1),
        dPhi_(2.0 * kPi / width), dTheta_(kPi / (height - 1)) {
    tabulated_ = dPhi_ <= kMaxStep && dTheta_ <= kMaxStep;
    if (!tabulated_) return;
    // Edge c of the columns (world φ) is the centre of texel c: u_map = (c + ½)/W.
    columnEdges_.resize(std::size_t(width));
    for (int c = 0; c < width; ++c) {
      const double phi = 2.0 * kPi * ((c + 0.5) / width - uOffset);
      columnEdges_[std::size_t(c)] = {std::cos(phi), std::sin(phi)};
    }
    // Edge r of the rows is texel row r: θ = πr/(H − 1).
    rowEdges_.resize(std::size_t(height));
    for (int r = 0; r < height; ++r) {
      const double theta = kPi * double(r) / double(rows_);
      rowEdges_[std::size_t(r)] = {std::cos(theta), std::sin(theta)};
    }
    rowEdges_.back() = {-1.0, 0.0};  // exactly the pole, as row 0 is
  }

  // The lookup position of unit direction d (x = u·W − ½ split into column c0 and weight fx, likewise y).
  LatLongPosition position(const Vec3& d) const {
    const double rho = std::sqrt(d.x * d.x + d.z * d.z);  // sin θ
    // Within 1e-4 of a pole the half-plane tests below lose their sign; the formulas cost nothing there.
    if (!tabulated_ || !(rho > 1e-4)) return latLongPosition(uvOf(d), width_, height_);

    const double y = std::clamp(d.y, -1.0, 1.0);
    // The row: θ ∈ [θ_r, θ_r+1), i.e. sin(θ − θ_r) = ρ cos θ_r − y sin θ_r ≥ 0 > sin(θ − θ_r+1), from a
    // guess good to 1e-5 rad, a small fraction of a row: the loops take a step now and then, rarely two.
    const double rowGuess = approxAtan2(rho, y) * (rows_ / kPi);
    int r = rowGuess > 0.0 ? std::min(int(rowGuess), rows_ - 1) : 0;
    auto aboveRowEdge = [&](int edge) {
      const Edge& e = rowEdges_[std::size_t(edge)];
      return rho * e.cos - y * e.sin;
    };
    while (r > 0 && aboveRowEdge(r) < 0.0) --r;
    while (r < rows_ - 1 && aboveRowEdge(r + 1) >= 0.0) ++r;
    const double fy = std::clamp(asinSmall(aboveRowEdge(r)) / dTheta_, 0.0, 1.0);

    // The column likewise: φ ∈ [e_c, e_c+1) with sin(φ − e) = (x cos e + z sin e)/ρ, as sin φ = x/ρ and
    // cos φ = −z/ρ.
    const double columnGuess = (approxAtan2(d.x, -d.z) * (0.5 * kInvPi) + uOffset_) * width_ - 0.5;
    int c = std::isfinite(columnGuess) ? int(std::floor(columnGuess)) % width_ : 0;
    if (c < 0) c += width_;
    auto pastColumnEdge = [&](int edge) {
      const Edge& e = columnEdges_[std::size_t(edge)];
      return d.x * e.cos + d.z * e.sin;
    };
    // Bounded loops: the tests cannot disagree for long, but a direction that is not unit must still end.
    for (int k = 0; k < width_ && pastColumnEdge(c) < 0.0; ++k) c = c == 0 ? width_ - 1 : c - 1;
    for (int k = 0; k < width_ && pastColumnEdge(next(c)) >= 0.0; ++k) c = next(c);
    const double fx = std::clamp(asinSmall(pastColumnEdge(c) / rho) / dPhi_, 0.0, 1.0);
    return {c, next(c), r, fx, fy};
  }

  // The unit direction at weights (fx, fy) in cell (column, row), and its sin θ.
  Vec3 direction(int column, int row, double fx, double fy, double& sinTheta) const {
    if (!tabulated_) {
      const double v = (row + fy) / rows_;
      const double uMap = wrapUnit((column + fx + 0.5) / width_);
      const double theta = kPi * v, phi = 2.0 * kPi * wrapUnit(uMap - uOffset_);
      sinTheta = std::sin(theta);
      return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
    }
    const Edge r = rowEdges_[std::size_t(row)], c = columnEdges_[std::size_t(column)];
    double sinT, cosT, sinP, cosP;
    sinCosSmall(fy * dTheta_, sinT, cosT);
    sinCosSmall(fx * dPhi_, sinP, cosP);
    // θ = θ_r + δθ, φ = e_c + δφ by the angle sums.
    sinTheta = r.sin * cosT + r.cos * sinT;
    const double cosTheta = r.cos * cosT - r.sin * sinT;
    const double sinPhi = c.sin * cosP + c.cos * sinP, cosPhi = c.cos * cosP - c.sin * sinP;
    return {sinTheta * sinPhi, cosTheta, -sinTheta * cosPhi};
  }

  // (u, v) in the map, by the spec's formulas.
  Vec2 uvOf(const Vec3& d) const {
    Vec2 uv = latLongFromDirection(d);
    uv.x = wrapUnit(uv.x + uOffset_);
    return uv;
  }

 private:
  struct Edge {
    double cos = 1.0, sin = 0.0;
  };

  int next(int column) const { return column + 1 == width_ ? 0 : column + 1; }

  // atan2 to about 1e-5 rad (Abramowitz & Stegun 4.4.49 on the octant): only a guess, corrected exactly.
  static double approxAtan2(double y, double x) {
    const double ax = std::abs(x), ay = std::abs(y), hi = std::max(ax, ay);
    const double t = hi > 0.0 ? std::min(ax, ay) / hi : 0.0, t2 = t * t;
    double a = t * (0.9998660 + t2 * (-0.3302995 + t2 * (0.1801410 + t2 * (-0.0851330 + t2 * 0.0208351))));
    if (ay > ax) a = 0.5 * kPi - a;
    if (x < 0.0) a = kPi - a;
    return y < 0.0 ? -a : a;
  }
  // asin t for |t| ≤ sin kMaxStep: the Taylor series to t⁹ (the next term is < 1e-19 of t).
  static double asinSmall(double t) {
    const double t2 = t * t;
    return t * (1.0 + t2 * (1.0 / 6.0 + t2 * (3.0 / 40.0 + t2 * (5.0 / 112.0 + t2 * (35.0 / 1152.0)))));
  }
  // sin and cos of |a| ≤ kMaxStep: Taylor series to a⁹ and a¹⁰.
  static void sinCosSmall(double a, double& s, double& c) {
    const double a2 = a * a;
    s = a * (1.0 - a2 / 6.0 * (1.0 - a2 / 20.0 * (1.0 - a2 / 42.0 * (1.0 - a2 / 72.0))));
    c = 1.0 - a2 / 2.0 * (1.0 - a2 / 12.0 * (1.0 - a2 / 30.0 * (1.0 - a2 / 56.0 * (1.0 - a2 / 90.0))));
  }

  int width_ = 0, height_ = 0;
  double uOffset_ = 0.0;
  int rows_ = 0;  // of cells: H − 1
  double dPhi_ = 0.0, dTheta_ = 0.0;
  bool tabulated_ = false;
  std::vector<Edge> columnEdges_, rowEdges_;
};

}  // namespace glossy
