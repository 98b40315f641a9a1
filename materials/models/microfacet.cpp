// Microfacet's batch forms (microfacet.h): the formulas of sampleLobe and evalPdf, lane by lane, as
// loops over arrays that the compiler vectorises, compiled as cook_torrance.cpp is (materials/CMakeLists.txt)
// and AVX2-cloned (GLOSSY_LANE_CLONES, lane_math.h). What depends on the model alone (the profile's
// integrals, the lobe's probability) is computed once per batch.
#include "materials/models/microfacet.h"

namespace glossy {

namespace {

// AbcProfile::invert(u.x, 1) for the lanes: expm1(log1p(u.x · expm1((1 − C) ln(1 + B))) / (1 − C)) / B, its
// C = 1 form expm1(u.x ln(1 + B)) / B, or u.x where B is negligible.
GLOSSY_LANE_CLONES
void oneMinusCosLanes(double b, double c, const Vec2* u, const bool* lobe, double* oneMinusCos, int n) {
  if (b < 1e-12) {
    for (int k = 0; k < n; ++k) oneMinusCos[k] = lobe[k] ? u[k].x : 0.0;
    return;
  }
  const double lMax = std::log1p(b), q = 1.0 - c;
  double x[kMaxBatchLanes] = {};  // initialised for GCC, which cannot see that the lane calls read only n
  if (std::abs(q * lMax) < 1e-10) {
    for (int k = 0; k < n; ++k) x[k] = lobe[k] ? u[k].x * lMax : 0.0;
  } else {
    const double top = std::expm1(q * lMax);
    for (int k = 0; k < n; ++k) x[k] = lobe[k] ? u[k].x * top : 0.0;
    lanes::log1p(x, x, n);
    for (int k = 0; k < n; ++k) x[k] /= q;
  }
  lanes::expm1(x, x, n);
  for (int k = 0; k < n; ++k) oneMinusCos[k] = x[k] / b;
}

GLOSSY_LANE_CLONES
void evalPdfLanes(const Microfacet& model, const Vec3* L, const Vec3* V, BrdfValue* out, int n) {
  constexpr int N = kMaxBatchLanes;
  const double p = model.specularProbability();
  const double lobeNorm = AbcProfile{model.b, model.c}.integral(1.0) * 2.0 * kPi * 4.0;
  // The lanes as arrays of coordinates; a lane below the horizon computes with a harmless stand-in and
  // is answered {} at the end, as evalPdf answers it.
  double lx[N], ly[N], lz[N], vx[N], vy[N], vz[N], specular[N], density[N];
  double profile[N] = {};  // initialised for GCC, which cannot see that the lane calls read only n of them
  for (int k = 0; k < n; ++k) {
    const bool valid = L[k].z > 0.0 && V[k].z > 0.0;
    lx[k] = valid ? L[k].x : 0.0;
    ly[k] = valid ? L[k].y : 0.0;
    lz[k] = valid ? L[k].z : 1.0;
    vx[k] = valid ? V[k].x : 0.0;
    vy[k] = valid ? V[k].y : 0.0;
    vz[k] = valid ? V[k].z : 1.0;
  }
  // (1 + B(1 − cos θ_h))^(−C), shared by the value and the density.
  for (int k = 0; k < n; ++k)
    profile[k] = model.b * HalfVector(Vec3(lx[k], ly[k], lz[k]), Vec3(vx[k], vy[k], vz[k])).oneMinusCosTheta;
  lanes::log1p(profile, profile, n);
  for (int k = 0; k < n; ++k) profile[k] *= -model.c;
  lanes::exp(profile, profile, n);
  for (int k = 0; k < n; ++k) {
    const Vec3 l(lx[k], ly[k], lz[k]);
    const LobeGeometry g(l, Vec3(vx[k], vy[k], vz[k]));
    specular[k] = Microfacet::lobe(g, profile[k], model.eta);
    // A select, not a branch, as everything here: the loop vectorises.
    const double lobeDensity = g.h.cosVH <= 0.0 ? 0.0 : profile[k] / (lobeNorm * g.h.cosVH);
    density[k] = mixtureDensity(p, p > 0.0 ? lobeDensity : 0.0, l);
  }
  for (int k = 0; k < n; ++k)
    out[k] = L[k].z > 0.0 && V[k].z > 0.0 ? BrdfValue{model.kd * kInvPi + model.a * specular[k], density[k]}
                                          : BrdfValue{};
}

}  // namespace

void Microfacet::lobeOneMinusCosBatch(const Vec2* u, const bool* lobe, double* oneMinusCos, int n) const {
  oneMinusCosLanes(b, c, u, lobe, oneMinusCos, n);
}

void Microfacet::evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const {
  evalPdfLanes(*this, L, V, out, n);
}

}  // namespace glossy
