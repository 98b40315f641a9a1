// A BRDF of any kind, by value: a handle on a shared, immutable BrdfModel (brdf_model.h). Copies share the
// model, nothing is allocated per evaluation, and a model registered at run time (registry.h) renders
// like a built-in one, at the cost of one virtual call per evaluation or batch.
#pragma once

#include "materials/models/brdf_model.h"
#include "materials/models/builtin_models.h"
#include "materials/models/measured.h"

#include <memory>

namespace glossy {

class Brdf {
 public:
  // Reflects nothing, as a default-constructed model does.
  Brdf() : Brdf(Lambertian{}) {}
  // Any model struct: Brdf b = Lambertian{Rgb(0.5)};
  template <ModelStruct M>
  Brdf(M model) : model_(std::make_shared<const BrdfAdapter<M>>(std::move(model))) {}
  explicit Brdf(std::shared_ptr<const BrdfModel> model) : model_(std::move(model)) {}

  const BrdfModel& model() const { return *model_; }
  const std::shared_ptr<const BrdfModel>& shared() const { return model_; }
  // The model struct behind the handle, or null when it is another model: if (auto s = brdf.as<Smooth>()) ...
  template <class M>
  const M* as() const {
    const auto* adapter = dynamic_cast<const BrdfAdapter<M>*>(model_.get());
    return adapter ? &adapter->model : nullptr;
  }

 private:
  std::shared_ptr<const BrdfModel> model_;
};

inline Rgb eval(const Brdf& brdf, const Vec3& L, const Vec3& V) { return brdf.model().eval(L, V); }
inline BrdfSample sample(const Brdf& brdf, const Vec3& V, double uLobe, Vec2 u) { return brdf.model().sample(V, uLobe, u); }
inline double pdf(const Brdf& brdf, const Vec3& L, const Vec3& V) { return brdf.model().pdf(L, V); }
// {eval, pdf} at once, for the models that share work between the two (the same values).
inline BrdfValue evalPdf(const Brdf& brdf, const Vec3& L, const Vec3& V) { return brdf.model().evalPdf(L, V); }

// A wave's BSDF samples and BRDF values: out[k] = sample(brdf, V[k], uLobe[k], u[k]), and
// evalPdf(brdf, L[k], V[k]), for k < n. Models with batch forms (brdf_sample.h) compute their
// transcendental functions for kMaxBatchLanes lanes at a time; the others are called lane by lane.
inline void sampleBatch(const Brdf& brdf, const Vec3* V, const double* uLobe, const Vec2* u, BrdfSample* out, int n) {
  brdf.model().sampleBatch(V, uLobe, u, out, n);
}
inline void evalPdfBatch(const Brdf& brdf, const Vec3* L, const Vec3* V, BrdfValue* out, int n) {
  brdf.model().evalPdfBatch(L, V, out, n);
}

// A measured BRDF that also proposes directions from an analytic lobe (its fit), with mixture weight q.
inline Measured withProposal(Measured m, const Brdf& lobe, double q) {
  m.proposal = lobe.shared();
  m.proposalWeight = q;
  return m;
}

}  // namespace glossy
