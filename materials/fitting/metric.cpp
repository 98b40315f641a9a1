#include "materials/fitting/metric.h"

#include "materials/core/input_error.h"

#include <cmath>

namespace glossy {

std::string_view metricName(Metric metric) { return metric == Metric::E1 ? "E1" : "E2"; }

Metric parseMetric(std::string_view text, std::string_view context) {
  if (text == "E1") return Metric::E1;
  if (text == "E2") return Metric::E2;
  throw InputError(std::string(context) + ": metric must be E1 or E2, got '" + std::string(text) + "'");
}

std::string MetricGrid::describe() {
  return "θi 90 × φi 180 × θo 15 (θi = i+½°, φi = ±2j°, θo = 5k+½°, φo = 0), nearest-bin MERL lookup";
}

MetricData::MetricData(const MerlTable& table, Metric metric) : metric_(metric), source_(table.source()) {
  points_.reserve(size_t(MetricGrid::kThetaO) * MetricGrid::kThetaI * (MetricGrid::kPhiI / 2 + 1));
  for (int k = 0; k < MetricGrid::kThetaO; ++k) {
    const double to = MetricGrid::thetaO(k);
    const Vec3 V(std::sin(to), 0.0, std::cos(to));
    for (int i = 0; i < MetricGrid::kThetaI; ++i) {
      const double ti = MetricGrid::thetaI(i), cosI = std::cos(ti), sinI = std::sin(ti);
      for (int j = 0; j <= MetricGrid::kPhiI / 2; ++j) {
        const double phi = MetricGrid::phiI(j);
        const Vec3 L(sinI * std::cos(phi), sinI * std::sin(phi), cosI);
        // The member at −φ_i (none for φ_i = 0° and 180°, which are their own mirror image).
        const bool mirrored = j != 0 && j != MetricGrid::kPhiI / 2;
        const Vec3 members[2] = {L, Vec3(L.x, -L.y, L.z)};
        Rgb t[2];
        int count = 0;
        for (int m = 0; m < (mirrored ? 2 : 1); ++m) {
          const size_t bin = MerlTable::binOf(members[m], V).index();
          if (!table.valid(bin)) continue;
          const Rgb rho = table.value(bin);
          if (!std::isfinite(rho.r) || !std::isfinite(rho.g) || !std::isfinite(rho.b))
            throw InputError(source_ + ": a measured value is not finite");
          t[count++] = Rgb(metricTransform(metric, rho.r, cosI), metricTransform(metric, rho.g, cosI),
                           metricTransform(metric, rho.b, cosI));
        }
        if (count == 0) continue;
        const Rgb mean = count == 2 ? 0.5 * (t[0] + t[1]) : t[0];
        if (count == 2) {
          const Rgb d = t[0] - t[1];
          constant_ += sinI * 0.5 * (d.r * d.r + d.g * d.g + d.b * d.b);  // Σ (t − mean)² over both members
        }
        points_.push_back({L, V, cosI, count * sinI, mean});
        weightSum_ += count * sinI;
        validPairs_ += count;
      }
    }
  }
  if (points_.empty())
    throw InputError(source_ + ": no measured bin on the fitting grid (all " + std::to_string(MetricGrid::kPairs) +
                     " direction pairs fall in unmeasured bins)");
}

double MetricData::error(const Brdf& brdf) const {
  double sum = 0.0;
  for (const Point& p : points_) {
    const Rgb rho = eval(brdf, p.L, p.V);
    const double r = metricTransform(metric_, rho.r, p.cosI) - p.target.r;
    const double g = metricTransform(metric_, rho.g, p.cosI) - p.target.g;
    const double b = metricTransform(metric_, rho.b, p.cosI) - p.target.b;
    sum += p.weight * (r * r + g * g + b * b);
  }
  return errorFromSum(sum);
}

}  // namespace glossy
