// What every BRDF offers the renderer, behind one virtual call: the interface a Brdf (brdf.h) holds, and
// BrdfAdapter, which implements it for any model struct.
//
// A model struct M provides, in the local shading frame (N = +z, L toward the light, V toward the viewer):
//   Rgb M::eval(L, V)                       ρ(L, V), 0 unless L_z > 0 and V_z > 0
//   BrdfSample M::sample(V, uLobe, u)       a direction L drawn from M's sampling density given V
//   double M::pdf(L, V)                     exactly that density, in solid angle
//   BrdfValue M::evalPdf(L, V)              optional: both at once, where they share work
//   lobeOneMinusCosBatch, evalPdfBatch      optional: batch forms for the path tracer (brdf_sample.h)
#pragma once

#include "materials/models/brdf_sample.h"

#include <algorithm>
#include <concepts>

namespace glossy {

class BrdfModel {
 public:
  virtual ~BrdfModel() = default;
  virtual Rgb eval(const Vec3& L, const Vec3& V) const = 0;
  virtual BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const = 0;
  virtual double pdf(const Vec3& L, const Vec3& V) const = 0;
  virtual BrdfValue evalPdf(const Vec3& L, const Vec3& V) const { return {eval(L, V), pdf(L, V)}; }
  // A wave's lanes: out[k] = sample(V[k], uLobe[k], u[k]), and evalPdf(L[k], V[k]), for k < n.
  virtual void sampleBatch(const Vec3* V, const double* uLobe, const Vec2* u, BrdfSample* out, int n) const {
    for (int k = 0; k < n; ++k) out[k] = sample(V[k], uLobe[k], u[k]);
  }
  virtual void evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const {
    for (int k = 0; k < n; ++k) out[k] = evalPdf(L[k], V[k]);
  }
};

template <class M>
concept ModelStruct = requires(const M& m, const Vec3& v, Vec2 u) {
  { m.eval(v, v) } -> std::same_as<Rgb>;
  { m.sample(v, 0.0, u) } -> std::same_as<BrdfSample>;
  { m.pdf(v, v) } -> std::same_as<double>;
};

// Model M behind the interface. Its batch forms, where it has them, compute their transcendental
// functions for kMaxBatchLanes lanes at a time; the others call M lane by lane, without a virtual call.
template <ModelStruct M>
class BrdfAdapter final : public BrdfModel {
 public:
  explicit BrdfAdapter(M m) : model(std::move(m)) {}
  const M model;

  Rgb eval(const Vec3& L, const Vec3& V) const override { return model.eval(L, V); }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const override { return model.sample(V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const override { return model.pdf(L, V); }
  BrdfValue evalPdf(const Vec3& L, const Vec3& V) const override { return evalWithPdf(model, L, V); }
  void sampleBatch(const Vec3* V, const double* uLobe, const Vec2* u, BrdfSample* out, int n) const override {
    if constexpr (HasBatchForms<M>) {
      for (int first = 0; first < n; first += kMaxBatchLanes)
        sampleMixtureBatch(model, V + first, uLobe + first, u + first, out + first, std::min(kMaxBatchLanes, n - first));
    } else {
      for (int k = 0; k < n; ++k) out[k] = model.sample(V[k], uLobe[k], u[k]);
    }
  }
  void evalPdfBatch(const Vec3* L, const Vec3* V, BrdfValue* out, int n) const override {
    if constexpr (HasBatchForms<M>) {
      for (int first = 0; first < n; first += kMaxBatchLanes)
        model.evalPdfBatch(L + first, V + first, out + first, std::min(kMaxBatchLanes, n - first));
    } else {
      for (int k = 0; k < n; ++k) out[k] = evalWithPdf(model, L[k], V[k]);
    }
  }
};

}  // namespace glossy
