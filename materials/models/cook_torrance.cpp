// Cook-Torrance's batch forms (cook_torrance.h): the formulas of sampleLobe and evalPdf, lane by
// lane, as loops over arrays that the compiler vectorises. This file is compiled without errno for sqrt
// and without trapping math (materials/CMakeLists.txt): neither changes a value, but each would keep a
// branch in the loops (a libm call for a negative sqrt; no speculated division under a select), and a
// branch stops vectorisation. The kernels are AVX2-cloned (GLOSSY_LANE_CLONES, lane_math.h).
#include "materials/models/cook_torrance.h"

namespace glossy {

namespace {

GLOSSY_LANE_CLONES
void oneMinusCosLanes(double m, const Vec2* u, const bool* lobe, double* oneMinusCos, int n) {
  double x[kMaxBatchLanes] = {};  // initialised for GCC, which cannot see that lanes::log1p reads only n
  for (int k = 0; k < n; ++k) x[k] = lobe[k] ? -u[k].x : 0.0;
  lanes::log1p(x, x, n);
  for (int k = 0; k < n; ++k) oneMinusCos[k] = CookTorrance::oneMinusCosOfTan2(-m * m * x[k]);
}

GLOSSY_LANE_CLONES
void evalPdfLanes(const CookTorrance& model, const Vec3* L, const Vec3* V, BrdfValue* out, int n) {
  constexpr int N = kMaxBatchLanes;
  const double m2 = model.m * model.m, p = model.specularProbability();
  // The lanes as arrays of coordinates; a lane below the horizon computes with a harmless stand-in and
  // is answered {} at the end, as evalPdf answers it.
  double lx[N], ly[N], lz[N], vx[N], vy[N], vz[N], specular[N], density[N];
  double beckmann[N] = {};  // initialised for GCC, which cannot see that lanes::exp reads only n of them
  for (int k = 0; k < n; ++k) {
    const bool valid = L[k].z > 0.0 && V[k].z > 0.0;
    lx[k] = valid ? L[k].x : 0.0;
    ly[k] = valid ? L[k].y : 0.0;
    lz[k] = valid ? L[k].z : 1.0;
    vx[k] = valid ? V[k].x : 0.0;
    vy[k] = valid ? V[k].y : 0.0;
    vz[k] = valid ? V[k].z : 1.0;
  }
  for (int k = 0; k < n; ++k)
    beckmann[k] = -HalfVector(Vec3(lx[k], ly[k], lz[k]), Vec3(vx[k], vy[k], vz[k])).tan2Theta / m2;
  lanes::exp(beckmann, beckmann, n);
  for (int k = 0; k < n; ++k) {
    const Vec3 l(lx[k], ly[k], lz[k]);
    const LobeGeometry g(l, Vec3(vx[k], vy[k], vz[k]));
    specular[k] = CookTorrance::lobe(g, m2, beckmann[k], model.eta);
    // Computed whether or not it is used: a call under a condition would be a branch.
    const double lobeDensity = model.lobePdf(g.h, beckmann[k]);
    density[k] = mixtureDensity(p, p > 0.0 ? lobeDensity : 0.0, l);
  }
  for (int k = 0; k < n; ++k)
    out[k] = L[k].z > 0.0 && V[k].z > 0.0 ? BrdfValue{model.kd * kInvPi + model.ks * specular[k], density[k]}
                                          : BrdfValue{};
}

}  // namespace

void CookTorrance::lobeOneMinusCosBatch(const Vec2* u, const bool* lobe, double* oneMinusCos, int n) const {
  oneMinusCosLanes(m, u, lobe, oneMinusCos, n);
}

void CookTorrance::evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const {
  evalPdfLanes(*this, L, V, out, n);
}

}  // namespace glossy
