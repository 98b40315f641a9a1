// Everything the four Löw et al. specular lobes read of a direction pair (L, V), computed once and without
// cancellation (see half_vector.h). The models evaluate their lobe from this, and the fitter computes it
// once per grid pair and then re-evaluates only the parameter-dependent part at every iteration.
#pragma once

#include "materials/models/half_vector.h"
#include "materials/models/vgroove.h"

namespace glossy {

struct LobeGeometry {
  double cosL, cosV;        // ⟨N,L⟩, ⟨N,V⟩ (both > 0)
  HalfVector h;             // ⟨N,H⟩, 1 − ⟨N,H⟩, tan²θ_h, ⟨V,H⟩
  double g;                 // V-groove shadowing-masking
  double dp2;               // ‖L_p + V_p‖² (Smooth: deviation from the mirror direction)
  double dm2;               // ‖L_p − V_p‖² (Smooth's [convention] Fresnel cosine is sqrt(1 − ¼ dm2))

  // L_z > 0 and V_z > 0.
  LobeGeometry(const Vec3& L, const Vec3& V)
      : cosL(L.z), cosV(V.z), h(L, V), g(vgrooveG(h.cosTheta, L.z, V.z, h.cosVH)) {
    const double dx = L.x + V.x, dy = L.y + V.y, ex = L.x - V.x, ey = L.y - V.y;
    dp2 = dx * dx + dy * dy;
    dm2 = ex * ex + ey * ey;
  }
};

// ρ = Kd/π + scale · lobe(shape), and 0 unless L and V are above the horizon: the eval() of a model with
// a specular lobe.
template <class M, size_t K>
Rgb evalLobeModel(const M& model, const Vec3& L, const Vec3& V, const Rgb& kd, const Rgb& scale, const double (&shape)[K]) {
  if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
  return kd * kInvPi + scale * model.lobe(LobeGeometry(L, V), shape);
}

}  // namespace glossy
