#include "materials/models/measured.h"

namespace glossy {

Measured::Measured(std::shared_ptr<const MerlTable> t)
    : table(std::move(t)), sampling(std::make_shared<const MerlSampling>(*table)), cosineWeight(kDefaultCosineWeight) {}

Measured Measured::cosineOnly(std::shared_ptr<const MerlTable> t) {
  Measured m;
  m.table = std::move(t);
  return m;
}

BrdfSample Measured::sample(const Vec3& V, double uLobe, Vec2 u) const {
  if (V.z <= 0.0) return {};
  const double c = sampling ? cosineWeight : 1.0 - proposalWeight;
  const double q = proposal ? proposalWeight : 0.0;
  BrdfSample s;
  if (uLobe < c) {
    s.L = squareToCosineHemisphere(u);
  } else if (uLobe < c + q) {
    s.L = proposal->sample(V, (uLobe - c) / q, u).L;
  } else {
    // The rest of uLobe picks between the two nearest view elevations' tables.
    if (!sampling->sample(V, (uLobe - c - q) / (1.0 - c - q), u, s.L)) return {};
  }
  if (s.L.z <= 0.0) return {};
  s.pdf = pdf(s.L, V);
  if (!(s.pdf > 0.0) || !std::isfinite(s.pdf)) return {};
  s.weight = eval(s.L, V) * (s.L.z / s.pdf);
  return s;
}

double Measured::pdf(const Vec3& L, const Vec3& V) const {
  if (V.z <= 0.0 || L.z <= 0.0) return 0.0;
  const double c = sampling ? cosineWeight : 1.0 - proposalWeight;
  const double q = proposal ? proposalWeight : 0.0;
  double p = c * L.z * kInvPi;
  if (q > 0.0) p += q * proposal->pdf(L, V);
  if (sampling && c + q < 1.0) p += (1.0 - c - q) * sampling->pdf(L, V);
  return p;
}

}  // namespace glossy
