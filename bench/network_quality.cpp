#include "bench/network_quality.h"

#include "renderer/plot/directional_albedo.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace glossy::bench {

namespace {

// One θ_h row's share of the figures; the rows are summed in order, so the result does not depend on threads.
struct RowSums {
  size_t measured = 0, nonFinite = 0;
  std::array<size_t, 3> negative{};
  std::array<double, 3> lowest{};
  double squaredDifference = 0.0, squaredMean = 0.0, asymmetryMax = 0.0;
};

}  // namespace

NetworkQuality assessNetwork(const NeuralBrdf& network, const MerlTable& table) {
  constexpr int nH = MerlTable::kThetaH, nD = MerlTable::kThetaD, nP = MerlTable::kPhiD;
  constexpr double degree = kPi / 180.0;
  std::vector<RowSums> rows(nH);
  tbb::parallel_for(0, nH, [&](int i) {
    RowSums& s = rows[size_t(i)];
    const double thetaH = double(i) * i / (nH * nH) * (kPi / 2.0);
    for (int j = 0; j < nD; ++j)
      for (int k = 0; k < nP; ++k) {
        if (!table.valid(MerlBin{i, j, k}.index())) continue;
        ++s.measured;
        const Rgb a = network.evalAngles(thetaH, j * degree, k * degree);
        const Rgb b = network.evalAngles(thetaH, j * degree, (k + 180) * degree);
        bool finite = true;
        for (int c = 0; c < 3; ++c) finite = finite && std::isfinite(a[c]) && std::isfinite(b[c]);
        if (!finite) {
          ++s.nonFinite;
          continue;
        }
        for (int c = 0; c < 3; ++c) {
          const double mean = 0.5 * (a[c] + b[c]), difference = std::abs(a[c] - b[c]);
          if (mean < 0.0) ++s.negative[size_t(c)], s.lowest[size_t(c)] = std::min(s.lowest[size_t(c)], mean);
          s.squaredDifference += difference * difference;
          s.squaredMean += mean * mean;
          if (mean >= NetworkQuality::kAsymmetryFloor) s.asymmetryMax = std::max(s.asymmetryMax, difference / mean);
        }
      }
  });

  NetworkQuality q;
  double squaredDifference = 0.0, squaredMean = 0.0;
  for (const RowSums& s : rows) {
    q.measuredBins += s.measured;
    q.nonFiniteBins += s.nonFinite;
    for (size_t c = 0; c < 3; ++c) q.negativeBins[c] += s.negative[c], q.lowest[c] = std::min(q.lowest[c], s.lowest[c]);
    squaredDifference += s.squaredDifference;
    squaredMean += s.squaredMean;
    q.asymmetryMax = std::max(q.asymmetryMax, s.asymmetryMax);
  }
  q.asymmetryRms = squaredMean > 0.0 ? std::sqrt(squaredDifference / squaredMean) : 0.0;

  std::vector<double> albedo(size_t(3) * NetworkQuality::kAlbedoAngles);
  tbb::parallel_for(0, 3 * NetworkQuality::kAlbedoAngles, [&](int n) {
    const int c = n % 3, angle = n / 3;
    albedo[size_t(n)] = plot::directionalAlbedo([&](const Vec3& L, const Vec3& V) { return table.eval(L, V)[c]; },
                                                5.0 * angle * degree);
  });
  for (int n = 0; n < 3 * NetworkQuality::kAlbedoAngles; ++n)
    if (albedo[size_t(n)] > q.maxAlbedo)
      q.maxAlbedo = albedo[size_t(n)], q.maxAlbedoChannel = n % 3, q.maxAlbedoThetaVDeg = 5.0 * (n / 3);
  return q;
}

}  // namespace glossy::bench
