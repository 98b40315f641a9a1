#include "tests/support/chi2.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace glossy::test {

namespace {

Vec3 direction(double theta, double phi) {
  const double s = std::sin(theta);
  return {s * std::cos(phi), s * std::sin(phi), std::cos(theta)};
}

// 7-point Gauss-Legendre on [−1, 1]: exact for polynomials of degree 13.
constexpr double kNodes[7] = {-0.9491079123427585, -0.7415311855993945, -0.4058451513773972, 0.0,
                              0.4058451513773972,  0.7415311855993945,  0.9491079123427585};
constexpr double kWeights[7] = {0.1294849661688697, 0.2797053914892766, 0.3818300505051189, 0.4179591836734694,
                                0.3818300505051189, 0.2797053914892766, 0.1294849661688697};

struct Rect {
  double a0, a1, b0, b1;
};

// ∫∫ g(a, b) da db over the rectangle.
using Integrand = std::function<double(double, double)>;

double gaussLegendre(const Rect& r, const Integrand& g) {
  const double ha = 0.5 * (r.a1 - r.a0), hb = 0.5 * (r.b1 - r.b0);
  const double ca = 0.5 * (r.a1 + r.a0), cb = 0.5 * (r.b1 + r.b0);
  double sum = 0.0;
  for (int i = 0; i < 7; ++i) {
    const double a = ca + ha * kNodes[i];
    double row = 0.0;
    for (int j = 0; j < 7; ++j) row += kWeights[j] * g(a, cb + hb * kNodes[j]);
    sum += kWeights[i] * row;
  }
  return sum * ha * hb;
}

// Splits into four until the four quarters agree with the whole; the tolerance is far below the Poisson
// noise of any cell (10⁶ samples: a relative 1e-3 on the fullest cell).
double adaptive(const Rect& r, double whole, const Integrand& g, int depth) {
  const double am = 0.5 * (r.a0 + r.a1), bm = 0.5 * (r.b0 + r.b1);
  const Rect q[4] = {{r.a0, am, r.b0, bm}, {am, r.a1, r.b0, bm}, {r.a0, am, bm, r.b1}, {am, r.a1, bm, r.b1}};
  double parts[4], sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += parts[k] = gaussLegendre(q[k], g);
  if (depth >= 10 || std::abs(sum - whole) <= 1e-9 * std::abs(sum) + 1e-14) return sum;
  sum = 0.0;
  for (int k = 0; k < 4; ++k) sum += adaptive(q[k], parts[k], g, depth + 1);
  return sum;
}

double integrateRect(const Rect& r, const Integrand& g) { return adaptive(r, gaussLegendre(r, g), g, 0); }

// Regularised upper incomplete gamma Q(a, x): series for P below x = a + 1, Lentz's continued fraction above.
double gammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  const double logPrefix = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 100000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    return std::max(0.0, 1.0 - sum * std::exp(logPrefix));
  }
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < 1e-16) break;
  }
  return std::exp(logPrefix) * h;
}

}  // namespace

LobeGrid::LobeGrid(const Vec3& centre, double sigma, int thetaCells, int phiCells) {
  thetaC_ = std::atan2(std::hypot(centre.x, centre.y), centre.z);
  phiC_ = (centre.x == 0.0 && centre.y == 0.0) ? 0.0 : std::atan2(centre.y, centre.x);
  thetaSigma_ = sigma;
  // Around the pole a lobe covers every φ: there the φ cells become uniform (σ_φ ≫ π).
  phiSigma_ = std::min(1e6, sigma / std::max(std::sin(thetaC_), 1e-300));

  tTheta0_ = std::asinh(-thetaC_ / thetaSigma_);
  dtTheta_ = (std::asinh((kPi / 2 - thetaC_) / thetaSigma_) - tTheta0_) / thetaCells;
  thetaEdges_.resize(thetaCells + 1);
  for (int i = 0; i <= thetaCells; ++i) thetaEdges_[i] = thetaC_ + thetaSigma_ * std::sinh(tTheta0_ + i * dtTheta_);
  thetaEdges_.front() = 0.0;
  thetaEdges_.back() = kPi / 2;

  tPhi0_ = -std::asinh(kPi / phiSigma_);
  dtPhi_ = -2.0 * tPhi0_ / phiCells;
  phiEdges_.resize(phiCells + 1);
  for (int j = 0; j <= phiCells; ++j) phiEdges_[j] = phiSigma_ * std::sinh(tPhi0_ + j * dtPhi_);
  phiEdges_.front() = -kPi;
  phiEdges_.back() = kPi;
}

int LobeGrid::cellOf(const Vec3& L) const {
  if (!(L.z > 0.0)) return -1;
  const double theta = std::atan2(std::hypot(L.x, L.y), L.z);
  const double phi = std::remainder(std::atan2(L.y, L.x) - phiC_, 2.0 * kPi);
  const int nt = int(thetaEdges_.size()) - 1, np = int(phiEdges_.size()) - 1;
  int i = int(std::floor((std::asinh((theta - thetaC_) / thetaSigma_) - tTheta0_) / dtTheta_));
  int j = int(std::floor((std::asinh(phi / phiSigma_) - tPhi0_) / dtPhi_));
  i = std::clamp(i, 0, nt - 1);
  j = std::clamp(j, 0, np - 1);
  // The edges were rounded at the ends and by sinh: settle the last ulp against the stored edges.
  while (i > 0 && theta < thetaEdges_[i]) --i;
  while (i < nt - 1 && theta >= thetaEdges_[i + 1]) ++i;
  while (j > 0 && phi < phiEdges_[j]) --j;
  while (j < np - 1 && phi >= phiEdges_[j + 1]) ++j;
  return i * np + j;
}

double LobeGrid::integrate(int cell, const std::function<double(const Vec3&)>& f) const {
  const int np = int(phiEdges_.size()) - 1;
  const int i = cell / np, j = cell % np;
  const Rect r{thetaEdges_[i], thetaEdges_[i + 1], phiC_ + phiEdges_[j], phiC_ + phiEdges_[j + 1]};
  return integrateRect(r, [&](double theta, double phi) { return f(direction(theta, phi)) * std::sin(theta); });
}

std::string LobeGrid::describe(int cell) const {
  const int np = int(phiEdges_.size()) - 1;
  const int i = cell / np, j = cell % np;
  std::ostringstream s;
  s << "θ ∈ [" << thetaEdges_[i] << ", " << thetaEdges_[i + 1] << "], φ−φc ∈ [" << phiEdges_[j] << ", "
    << phiEdges_[j + 1] << "]";
  return s.str();
}

HalfVectorGrid::HalfVectorGrid(const Vec3& V, std::vector<double> xEdges, int phiCells)
    : V_(V), phiV_(std::atan2(V.y, V.x)), xEdges_(std::move(xEdges)), phiCells_(phiCells) {}

int HalfVectorGrid::cellOf(const Vec3& L) const {
  if (!(L.z > 0.0)) return -1;
  const Vec3 h = L + V_;
  const double p2 = h.x * h.x + h.y * h.y, len = std::sqrt(p2 + h.z * h.z);
  const double x = p2 / (len * (len + h.z));  // 1 − cos θ_h without cancellation
  const int nx = int(xEdges_.size()) - 1;
  const int i = std::clamp(int(std::upper_bound(xEdges_.begin(), xEdges_.end(), x) - xEdges_.begin()) - 1, 0, nx - 1);
  const double rel = std::remainder(std::atan2(h.y, h.x) - phiV_, 2.0 * kPi);
  const int j = std::clamp(int(std::floor((rel + kPi) / (2.0 * kPi) * phiCells_)), 0, phiCells_ - 1);
  return i * phiCells_ + j;
}

namespace {

double gaussLegendre1D(double a, double b, const std::function<double(double)>& g) {
  const double h = 0.5 * (b - a), c = 0.5 * (a + b);
  double sum = 0.0;
  for (int i = 0; i < 7; ++i) sum += kWeights[i] * g(c + h * kNodes[i]);
  return sum * h;
}

double adaptive1D(double a, double b, double whole, const std::function<double(double)>& g, int depth) {
  const double m = 0.5 * (a + b);
  const double left = gaussLegendre1D(a, m, g), right = gaussLegendre1D(m, b, g);
  if (depth >= 30 || std::abs(left + right - whole) <= 1e-10 * std::abs(left + right) + 1e-16) return left + right;
  return adaptive1D(a, m, left, g, depth + 1) + adaptive1D(m, b, right, g, depth + 1);
}

double integrate1D(double a, double b, const std::function<double(double)>& g) {
  return adaptive1D(a, b, gaussLegendre1D(a, b, g), g, 0);
}

}  // namespace

double HalfVectorGrid::integrate(int cell, const std::function<double(const Vec3&)>& f) const {
  const int i = cell / phiCells_, j = cell % phiCells_;
  const double dphi = 2.0 * kPi / phiCells_;
  const Rect r{xEdges_[i], xEdges_[i + 1], phiV_ - kPi + j * dphi, phiV_ - kPi + (j + 1) * dphi};
  const auto halfVector = [](double x, double phi) {
    const double s = std::sqrt(std::max(0.0, x * (2.0 - x)));
    return Vec3(s * std::cos(phi), s * std::sin(phi), 1.0 - x);
  };
  // L_z of the reflection (−1 where ⟨V,H⟩ ≤ 0): the horizon is where it changes sign.
  const auto reflectedZ = [&](double x, double phi) {
    const Vec3 H = halfVector(x, phi);
    const double vh = V_.x * H.x + V_.y * H.y + V_.z * H.z;
    return vh <= 0.0 ? -1.0 : 2.0 * vh * H.z - V_.z;
  };
  const auto g = [&](double x, double phi) {
    const Vec3 H = halfVector(x, phi);
    const double vh = V_.x * H.x + V_.y * H.y + V_.z * H.z;
    if (vh <= 0.0) return 0.0;
    const Vec3 L = 2.0 * vh * H - V_;
    return L.z > 0.0 ? f(L) * 4.0 * vh : 0.0;
  };
  int above = 0, probes = 0;
  for (int a = 0; a <= 4; ++a)
    for (int b = 0; b <= 4; ++b, ++probes)
      above += reflectedZ(r.a0 + (r.a1 - r.a0) * a / 4, r.b0 + (r.b1 - r.b0) * b / 4) > 0.0;
  if (above == 0) return 0.0;
  if (above == probes) return integrateRect(r, g);
  // The cell straddles the horizon, where a tabulated density jumps to 0: integrate along x only up to
  // the crossing (found by bisection for each φ), so that each inner integral is smooth.
  return integrate1D(r.b0, r.b1, [&](double phi) {
    const double za = reflectedZ(r.a0, phi), zb = reflectedZ(r.a1, phi);
    if (za <= 0.0 && zb <= 0.0) return 0.0;
    const auto inner = [&](double lo, double hi) { return integrate1D(lo, hi, [&](double x) { return g(x, phi); }); };
    if (za > 0.0 && zb > 0.0) return inner(r.a0, r.a1);
    double inside = za > 0.0 ? r.a0 : r.a1, outside = za > 0.0 ? r.a1 : r.a0;
    for (int k = 0; k < 60; ++k) {
      const double m = 0.5 * (inside + outside);
      (reflectedZ(m, phi) > 0.0 ? inside : outside) = m;
    }
    return za > 0.0 ? inner(r.a0, inside) : inner(inside, r.a1);
  });
}

std::string HalfVectorGrid::describe(int cell) const {
  const int i = cell / phiCells_, j = cell % phiCells_;
  std::ostringstream s;
  s << "1 − cos θ_h ∈ [" << xEdges_[i] << ", " << xEdges_[i + 1] << "], φ_h − φ_v cell " << j << " of " << phiCells_;
  return s.str();
}

Chi2Result chi2Test(const DirectionSampler& sampler, const DirectionPdf& pdf, const Chi2Grid& grid, long samples,
                    unsigned seed, double alpha) {
  Chi2Result result;
  const int cells = grid.cellCount();
  const int invalidCell = cells;
  std::vector<double> observed(cells + 1, 0.0), expected(cells + 1, 0.0);

  std::mt19937_64 rng(seed);
  long belowHorizon = 0, nonFinite = 0;
  for (long k = 0; k < samples; ++k) {
    const std::optional<Vec3> L = sampler(rng);
    if (!L) {
      observed[invalidCell] += 1;
      continue;
    }
    if (!std::isfinite(L->x) || !std::isfinite(L->y) || !std::isfinite(L->z)) {
      ++nonFinite;
      continue;
    }
    const int c = grid.cellOf(*L);
    if (c < 0) {
      ++belowHorizon;
      continue;
    }
    observed[c] += 1;
  }
  result.acceptance = 1.0 - observed[invalidCell] / double(samples);

  double integral = 0.0;
  for (int c = 0; c < cells; ++c) {
    const double p = grid.integrate(c, pdf);
    integral += p;
    expected[c] = p * double(samples);
  }
  result.pdfIntegral = integral;
  expected[invalidCell] = std::max(0.0, 1.0 - integral) * double(samples);

  std::ostringstream summary;
  summary << "∫pdf = " << integral << ", acceptance = " << result.acceptance << " (" << samples << " samples)";
  if (nonFinite > 0 || belowHorizon > 0) {
    result.message = summary.str() + "; " + std::to_string(nonFinite) + " non-finite and " +
                     std::to_string(belowHorizon) + " below-horizon directions marked valid";
    return result;
  }
  // ∫pdf > 1 beyond quadrature error: the pdf cannot be any sampler's density.
  if (integral > 1.0 + 1e-7) {
    result.message = summary.str() + "; the pdf integrates to more than 1";
    return result;
  }
  for (int c = 0; c < cells; ++c)
    if (expected[c] == 0.0 && observed[c] > 0.0) {
      result.message = summary.str() + "; " + std::to_string(long(observed[c])) +
                       " samples where the pdf is 0: " + grid.describe(c);
      return result;
    }

  // Pool the cells expected to hold fewer than 5 samples (the χ² approximation needs ≥ 5 per cell).
  std::vector<int> order(cells + 1);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return expected[a] < expected[b]; });
  double poolE = 0.0, poolO = 0.0;
  std::vector<int> kept;
  for (int c : order) {
    if (expected[c] < 5.0) {
      poolE += expected[c];
      poolO += observed[c];
      ++result.pooledCells;
    } else {
      kept.push_back(c);
    }
  }
  struct Term {
    double o, e;
    int cell;  // −1: the pool
  };
  std::vector<Term> terms;
  for (int c : kept) terms.push_back({observed[c], expected[c], c});
  if (poolE >= 5.0 || terms.empty()) {
    terms.push_back({poolO, poolE, -1});
  } else if (poolE > 0.0 || poolO > 0.0) {
    terms.front().o += poolO;  // the smallest kept cell absorbs a pool too small to stand alone
    terms.front().e += poolE;
  }
  double chi2 = 0.0;
  for (const Term& t : terms)
    if (t.e > 0.0) chi2 += (t.o - t.e) * (t.o - t.e) / t.e;
  result.cells = int(terms.size());
  result.degreesOfFreedom = std::max(1, result.cells - 1);
  result.statistic = chi2;
  result.pValue = chi2Survival(chi2, result.degreesOfFreedom);
  result.passed = result.pValue >= alpha;

  summary << "; χ² = " << chi2 << " with " << result.degreesOfFreedom << " dof (" << result.pooledCells
          << " cells pooled), p = " << result.pValue << " vs α = " << alpha;
  if (!result.passed) {
    std::sort(terms.begin(), terms.end(), [](const Term& a, const Term& b) {
      return (a.o - a.e) * (a.o - a.e) / a.e > (b.o - b.e) * (b.o - b.e) / b.e;
    });
    summary << "; worst cells:";
    for (size_t k = 0; k < std::min<size_t>(4, terms.size()); ++k) {
      const Term& t = terms[k];
      summary << "\n  observed " << t.o << ", expected " << t.e << " in "
              << (t.cell < 0 ? std::string("the pooled cells")
                  : t.cell == invalidCell ? std::string("the rejected samples")
                                          : grid.describe(t.cell));
    }
  }
  result.message = summary.str();
  return result;
}

double sidakAlpha(double familyAlpha, int tests) { return -std::expm1(std::log1p(-familyAlpha) / tests); }

double chi2Survival(double x, int dof) { return gammaQ(0.5 * dof, 0.5 * x); }

PooledChi2 pooledChi2(const std::vector<double>& observed, const std::vector<double>& expected, double minExpected) {
  PooledChi2 r;
  double pooledObserved = 0.0, pooledExpected = 0.0;
  for (std::size_t b = 0; b < observed.size() && b < expected.size(); ++b) {
    if (expected[b] < minExpected) {
      pooledObserved += observed[b];
      pooledExpected += expected[b];
      continue;
    }
    r.statistic += (observed[b] - expected[b]) * (observed[b] - expected[b]) / expected[b];
    ++r.bins;
  }
  if (pooledExpected >= minExpected) {
    r.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++r.bins;
  }
  r.p = r.bins > 1 ? chi2Survival(r.statistic, r.bins - 1) : 1.0;
  return r;
}

}  // namespace glossy::test
