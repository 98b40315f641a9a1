#include "materials/fitting/fitter.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/models/common_params.h"
#include "materials/models/registry.h"

#include <ceres/ceres.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

namespace glossy {

namespace {

// Kd and the scale, as logarithms: 1e-9 reads as 0 in any render; the scale stops where parameter files
// stop (common_params.h), so that every fit the fitter makes can be written and read back.
constexpr double kLinearLo = 1e-9, kKdHi = 10.0, kScaleHi = params::kScaleRange.hi;

template <class M>
concept Fittable = requires(const M& m, const LobeGeometry& g, const double* s) {
  { M::kShape };
  { M::kScaleKey };
  { m.lobe(g, s) };
};

// A grid point with its geometry computed once.
struct FitPoint {
  LobeGeometry geom;
  double cosI, sqrtWeight;
  std::array<double, 3> target;
};

template <class T>
T fromUnconstrained(FitScale scale, const T& x) {
  using std::exp;
  return scale == FitScale::Log ? exp(x) : 1.0 + exp(x);
}
double toUnconstrained(FitScale scale, double v) { return std::log(scale == FitScale::Log ? v : v - 1.0); }

// The weighted residuals of a run of points, r = sqrt(w) (T(ρ_model) − target) per channel, with their
// Jacobian. ρ = Kd/π + scale · lobe(shape) is linear in Kd and the scale, so only the lobe is
// differentiated (forward mode in the K shape parameters); the rest of the chain rule is written out,
// which makes an iteration several times cheaper than automatic differentiation in all 6 + K parameters.
template <class M>
class ChunkCost final : public ceres::CostFunction {
 public:
  static constexpr int kShapes = int(std::size(M::kShape));
  using Jet = ceres::Jet<double, kShapes>;

  ChunkCost(const FitPoint* points, int count, Metric metric, const M& model)
      : points_(points), count_(count), metric_(metric), model_(model) {
    set_num_residuals(3 * count);
    *mutable_parameter_block_sizes() = {3, 3, kShapes};
  }

  bool Evaluate(double const* const* x, double* r, double** jacobians) const override {
    double kd[3], scale[3];
    for (int c = 0; c < 3; ++c) kd[c] = std::exp(x[0][c]) * kInvPi, scale[c] = std::exp(x[1][c]);
    Jet shape[kShapes];
    for (int k = 0; k < kShapes; ++k) shape[k] = fromUnconstrained(M::kShape[k].scale, Jet(x[2][k], k));
    double* jKd = jacobians ? jacobians[0] : nullptr;
    double* jScale = jacobians ? jacobians[1] : nullptr;
    double* jShape = jacobians ? jacobians[2] : nullptr;
    for (int i = 0; i < count_; ++i) {
      const FitPoint& p = points_[i];
      const Jet lobe = model_.lobe(p.geom, shape);
      for (int c = 0; c < 3; ++c) {
        const int row = 3 * i + c;
        const double u = (kd[c] + scale[c] * lobe.a) * p.cosI;
        const double v = metric_ == Metric::E2 ? std::log1p(u) : u;
        r[row] = p.sqrtWeight * (v - p.target[c]);
        if (!jacobians) continue;
        const double dr = p.sqrtWeight * (metric_ == Metric::E2 ? 1.0 / (1.0 + u) : 1.0) * p.cosI;  // ∂r/∂ρ
        if (jKd) {
          for (int k = 0; k < 3; ++k) jKd[3 * row + k] = 0.0;
          jKd[3 * row + c] = dr * kd[c];  // ∂Kd/∂x = Kd (x = log Kd)
        }
        if (jScale) {
          for (int k = 0; k < 3; ++k) jScale[3 * row + k] = 0.0;
          jScale[3 * row + c] = dr * scale[c] * lobe.a;
        }
        if (jShape)
          for (int k = 0; k < kShapes; ++k) jShape[kShapes * row + k] = dr * scale[c] * lobe.v[k];
      }
    }
    return true;
  }

 private:
  const FitPoint* points_;
  int count_;
  Metric metric_;
  M model_;  // carries the choices that are not fitted (Smooth's Fresnel cosine)
};

struct Candidate {
  std::array<double, 3> kd, scale;
  std::vector<double> shape;  // values, not unconstrained
  double sum = std::numeric_limits<double>::infinity();  // Σ w (T(ρ) − t)² over the points
  size_t width = 0;           // index of the first shape parameter's start (the lobe width)
};

double weightedSquares(const std::vector<FitPoint>& pts, Metric metric, const std::vector<double>& lobe,
                       const std::array<double, 3>& kd, const std::array<double, 3>& scale) {
  double sum = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double r = metricTransform(metric, kd[c] * kInvPi + scale[c] * lobe[i], pts[i].cosI) - pts[i].target[c];
      sum += pts[i].sqrtWeight * pts[i].sqrtWeight * r * r;
    }
  }
  return sum;
}

// Kd and scale per channel for a fixed lobe: linear least squares on ρ cos θ_i (E2: weighted by the
// derivative of ln(1 + x), 1/(1 + x)², about the data), clipped to the lower bound.
void solveLinear(const std::vector<FitPoint>& pts, Metric metric, const std::vector<double>& lobe, Candidate& c) {
  for (int ch = 0; ch < 3; ++ch) {
    double saa = 0, sab = 0, sbb = 0, sat = 0, sbt = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
      const FitPoint& p = pts[i];
      double w = p.sqrtWeight * p.sqrtWeight, t = p.target[ch];
      if (metric == Metric::E2) {
        const double x = std::expm1(t);
        w /= (1.0 + x) * (1.0 + x);
        t = x;
      }
      const double a = p.cosI * kInvPi, b = p.cosI * lobe[i];
      saa += w * a * a, sab += w * a * b, sbb += w * b * b, sat += w * a * t, sbt += w * b * t;
    }
    double kd = 0, s = 0;
    const double det = saa * sbb - sab * sab;
    if (det > 1e-300 * saa * sbb) {
      kd = (sat * sbb - sbt * sab) / det;
      s = (sbt * saa - sat * sab) / det;
    }
    if (!(kd > 0.0) || !(s > 0.0)) {  // one of them at its bound: the best of the two one-term fits
      const double sOnly = sbb > 0 ? std::max(sbt / sbb, 0.0) : 0.0, kdOnly = saa > 0 ? std::max(sat / saa, 0.0) : 0.0;
      const double eS = -2 * sOnly * sbt + sOnly * sOnly * sbb, eK = -2 * kdOnly * sat + kdOnly * kdOnly * saa;
      if (eS < eK) kd = 0, s = sOnly;
      else kd = kdOnly, s = 0;
    }
    c.kd[ch] = std::clamp(kd, kLinearLo, kKdHi);
    c.scale[ch] = std::clamp(s, kLinearLo, kScaleHi);
  }
}

template <class M>
std::vector<double> lobeValues(const M& model, const std::vector<FitPoint>& pts, const std::vector<double>& shape) {
  std::vector<double> lobe(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) lobe[i] = model.lobe(pts[i].geom, shape.data());
  return lobe;
}

template <class M>
Candidate refine(const M& model, const std::vector<FitPoint>& pts, Metric metric, Candidate start,
                 const FitSettings& settings) {
  constexpr int K = ChunkCost<M>::kShapes;
  constexpr int kChunk = 256;
  double xKd[3], xScale[3], xShape[K];
  for (int c = 0; c < 3; ++c) xKd[c] = std::log(start.kd[c]), xScale[c] = std::log(start.scale[c]);
  for (int k = 0; k < K; ++k) xShape[k] = toUnconstrained(M::kShape[k].scale, start.shape[k]);

  ceres::Problem problem;
  for (size_t first = 0; first < pts.size(); first += kChunk) {
    const int n = int(std::min<size_t>(kChunk, pts.size() - first));
    problem.AddResidualBlock(new ChunkCost<M>(pts.data() + first, n, metric, model), nullptr, xKd, xScale, xShape);
  }
  for (int c = 0; c < 3; ++c) {
    problem.SetParameterLowerBound(xKd, c, std::log(kLinearLo));
    problem.SetParameterUpperBound(xKd, c, std::log(kKdHi));
    problem.SetParameterLowerBound(xScale, c, std::log(kLinearLo));
    problem.SetParameterUpperBound(xScale, c, std::log(kScaleHi));
  }
  for (int k = 0; k < K; ++k) {
    const ShapeParam& p = M::kShape[k];
    problem.SetParameterLowerBound(xShape, k, toUnconstrained(p.scale, p.lo));
    problem.SetParameterUpperBound(xShape, k, toUnconstrained(p.scale, p.hi));
    xShape[k] = std::clamp(xShape[k], toUnconstrained(p.scale, p.lo), toUnconstrained(p.scale, p.hi));
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_NORMAL_CHOLESKY;  // 9 × 9 normal equations; LM damps them
  options.max_num_iterations = settings.maxIterations;
  options.num_threads = 1;
  options.function_tolerance = 1e-12;
  options.gradient_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  Candidate out = start;
  // exp(log(bound)) can land an ulp outside the bound: clamped, so that a value at its bound stays valid.
  for (int c = 0; c < 3; ++c)
    out.kd[c] = std::clamp(std::exp(xKd[c]), kLinearLo, kKdHi), out.scale[c] = std::clamp(std::exp(xScale[c]), kLinearLo, kScaleHi);
  for (int k = 0; k < K; ++k)
    out.shape[k] = std::clamp(fromUnconstrained(M::kShape[k].scale, xShape[k]), M::kShape[k].lo, M::kShape[k].hi);
  out.sum = std::isfinite(summary.final_cost) ? 2.0 * summary.final_cost : std::numeric_limits<double>::infinity();
  // Never worse than the start (a failed solve keeps it).
  return out.sum <= start.sum ? out : start;
}

template <class M>
FitReport fitWith(const MetricData& data, const FitSettings& settings) {
  const auto t0 = std::chrono::steady_clock::now();
  constexpr int K = ChunkCost<M>::kShapes;
  const M model{};
  const Metric metric = data.metric();

  std::vector<FitPoint> pts;
  pts.reserve(data.points().size());
  for (const auto& p : data.points())
    pts.push_back({LobeGeometry(p.L, p.V), p.cosI, std::sqrt(p.weight), {p.target.r, p.target.g, p.target.b}});

  // The scan: every combination of the shape parameters' starts, numbered with the last one varying fastest.
  size_t combos = 1;
  for (const ShapeParam& p : M::kShape) combos *= p.starts.size();

  const int threads = settings.threads > 0 ? settings.threads : int(tbb::this_task_arena::max_concurrency());
  tbb::task_arena arena(threads);
  std::vector<Candidate> scanned(combos);
  arena.execute([&] {
    tbb::parallel_for(size_t(0), combos, [&](size_t i) {
      Candidate c;
      c.shape.resize(K);
      size_t rest = i;
      for (int k = K - 1; k >= 0; --k) {
        const std::span<const double> starts = M::kShape[k].starts;
        c.width = rest % starts.size();  // left at the first parameter's start: the lobe width
        c.shape[k] = starts[c.width];
        rest /= starts.size();
      }
      const std::vector<double> lobe = lobeValues(model, pts, c.shape);
      solveLinear(pts, metric, lobe, c);
      c.sum = weightedSquares(pts, metric, lobe, c.kd, c.scale);
      if (!std::isfinite(c.sum)) c.sum = std::numeric_limits<double>::infinity();
      scanned[i] = c;
    });
  });

  // The best start of each lobe width, then the best widths.
  std::vector<Candidate> perWidth;
  for (const Candidate& c : scanned) {
    auto same = std::find_if(perWidth.begin(), perWidth.end(), [&](const Candidate& o) { return o.width == c.width; });
    if (same == perWidth.end()) perWidth.push_back(c);
    else if (c.sum < same->sum) *same = c;
  }
  std::stable_sort(perWidth.begin(), perWidth.end(), [](const Candidate& a, const Candidate& b) { return a.sum < b.sum; });
  perWidth.resize(std::min<size_t>(perWidth.size(), size_t(std::max(1, settings.refinedStarts))));
  if (!std::isfinite(perWidth.front().sum))
    throw InputError(data.source() + ": the fit failed: no start gives a finite " + std::string(metricName(metric)));

  std::vector<Candidate> refined(perWidth.size());
  arena.execute([&] {
    tbb::parallel_for(size_t(0), perWidth.size(), [&](size_t i) { refined[i] = refine(model, pts, metric, perWidth[i], settings); });
  });

  FitReport report;
  report.scanned = scanned.size();
  size_t best = 0;
  for (size_t i = 0; i < refined.size(); ++i) {
    report.startErrors.push_back(data.errorFromSum(refined[i].sum));
    if (refined[i].sum < refined[best].sum) best = i;
  }
  const Candidate& b = refined[best];

  Fit& fit = report.fit;
  fit.id = {std::string(M::kName), std::string(metricName(metric))};
  fit.params.set("kd", Rgb(b.kd[0], b.kd[1], b.kd[2]));
  fit.params.set(std::string(M::kScaleKey), Rgb(b.scale[0], b.scale[1], b.scale[2]));
  for (int k = 0; k < K; ++k) fit.params.set(std::string(M::kShape[k].key), b.shape[k]);
  validateFit(fit, data.source() + ": fitted " + fit.id.str());
  report.error = data.error(makeBrdf(fit));
  fit.error = report.error;
  fit.settings = settings.describe();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

// The built-in models the fitter can fit (a model registered at run time has no static type to fit).
template <class M>
bool fitIfNamed(std::string_view name, const MetricData& data, const FitSettings& s, FitReport& out) {
  if constexpr (Fittable<M>) {
    if (M::kName != name) return false;
    out = fitWith<M>(data, s);
    return true;
  }
  return false;
}
template <class... M>
bool dispatch(ModelList<M...>, std::string_view name, const MetricData& data, const FitSettings& s, FitReport& out) {
  return (fitIfNamed<M>(name, data, s, out) || ...);
}
template <class... M>
bool canFit(ModelList<M...>, std::string_view name) {
  return ((Fittable<M> && M::kName == name) || ...);
}

}  // namespace

std::string FitSettings::describe() const {
  std::ostringstream s;
  s << "glossy " << GLOSSY_VERSION << " fit: grid " << MetricGrid::describe() << "; coarse scan of the shape starts, best "
    << refinedStarts << " lobe widths refined by Ceres Levenberg-Marquardt (≤ " << maxIterations << " iterations)";
  return s.str();
}

std::vector<std::string_view> fittableModels() {
  std::vector<std::string_view> names;
  for (const ModelInfo& m : analyticModels())
    if (canFit(BuiltinModels{}, m.name)) names.push_back(m.name);
  return names;
}

std::string fittableModelNames() { return joined(fittableModels(), ", "); }

void requireFittable(std::string_view model, std::string_view option) {
  if (!canFit(BuiltinModels{}, model))
    throw InputError(std::string(option) + ": cannot fit '" + std::string(model) + "' (fittable: " + fittableModelNames() + ")");
}

FitReport fitModel(const MetricData& data, std::string_view model, const FitSettings& settings) {
  requireFittable(model);
  FitReport report;
  dispatch(BuiltinModels{}, model, data, settings, report);
  return report;
}

}  // namespace glossy
