// Lambertian:  ρ = Kd / π.  The diffuse term of all four Löw et al. models, and glTF's baseColor.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"

namespace glossy {

struct Lambertian {
  static constexpr std::string_view kName = "lambertian";
  static constexpr std::string_view kLabel = "Lambertian";
  static constexpr ParamSpec kParams[] = {
      params::kKd,
  };
  static Lambertian fromParams(const ParamSet& p) { return {p.rgb("kd")}; }

  Rgb kd{0.0};

  Rgb eval(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
    return kd * kInvPi;
  }
  BrdfSample sample(const Vec3& V, double /*uLobe*/, Vec2 u) const { return sampleCosineLobe(*this, V, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return V.z > 0.0 ? cosineHemispherePdf(L) : 0.0; }
};

}  // namespace glossy
