// Fitting an analytic model to measured data under E1 or E2 (Löw et al. 2012), with Ceres.
//
// Kd and the scale (A or Ks) are per channel, the shape parameters (B, C, m, n, η: each model's kShape)
// shared. All are fitted as unconstrained logarithms (η as log(η − 1)) within each parameter's bounds.
// The start does not come from luck: a coarse scan over every combination of the model's shape starts,
// with Kd and the scale solved by linear least squares at each, ranks the lobe widths; the best
// `refinedStarts` widths (one start each) are refined by Levenberg-Marquardt, in parallel and each on one
// thread so that the result is the same on any machine and thread count, and the lowest E wins.
#pragma once

#include "materials/fitting/metric.h"
#include "materials/params/material_file.h"

#include <string>
#include <string_view>
#include <vector>

namespace glossy {

struct FitSettings {
  int refinedStarts = 4;
  int maxIterations = 200;
  int threads = 0;  // 0: all cores
  std::string describe() const;  // recorded in the fit's `settings`
};

struct FitReport {
  Fit fit;                          // validated; fit.error and fit.settings are set
  double error = 0.0;               // E of the fit under its metric (MetricData::error of the result)
  size_t scanned = 0;               // scan points evaluated
  std::vector<double> startErrors;  // E each refined start reached, best scan point first
  double seconds = 0.0;
};

// The registry's models with a fittable lobe (kShape, kScaleKey, lobe()), in its order; and as one string.
std::vector<std::string_view> fittableModels();
std::string fittableModelNames();
// InputError naming the fittable models unless `model` is one.
void requireFittable(std::string_view model, std::string_view option = "--model");

// Throws InputError for a model that cannot be fitted, and for data on which the fit fails.
FitReport fitModel(const MetricData& data, std::string_view model, const FitSettings& settings = {});

}  // namespace glossy
