// The parameters of one fit, and the declaration each model makes of the parameters it takes.
// The parameter-file loader validates against a model's ParamSpec list, so a model declares its keys,
// kinds and ranges once and the loader, writer and importer follow.
#pragma once

#include "materials/core/types.h"

#include <limits>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace glossy {

enum class ParamKind { Rgb, Scalar, Choice };
// The closed interval a scalar parameter, or each channel of an RGB one, must lie in. A model's ranges keep
// its eval, sample and pdf finite everywhere inside them (model_ranges_test checks the ends): values a
// parser accepts as "positive", such as m = 1e-308 or eta = 1e308, otherwise evaluate to NaN.
// docs/materials.md lists every model's.
struct ParamRange {
  double lo = -std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::max();
};

struct ParamSpec {
  std::string_view key;
  ParamKind kind;
  ParamRange range = {};
  std::string_view meaning;
  std::span<const std::string_view> choices = {};  // ParamKind::Choice only; the first is the default
  bool optional = false;
};

// How the fitter (materials/fitting) varies one of a model's shape parameters (the ones its lobe is
// nonlinear in): as the unconstrained x of v = e^x (Log) or v = 1 + e^x (AboveOne), within [lo, hi], starting
// from each of `starts` in a coarse scan. The per-channel Kd and scale are always fitted, on a log scale.
enum class FitScale { Log, AboveOne };
struct ShapeParam {
  std::string_view key;
  FitScale scale;
  double lo, hi;
  std::span<const double> starts;
};

// Human text for a range: "in [0.0001, 10]".
std::string describeRange(ParamRange range);
bool inRange(double value, ParamRange range);  // false for NaN

class ParamSet {
 public:
  using Value = std::variant<double, Rgb, std::string>;

  void set(std::string key, Value value) { values_[std::move(key)] = std::move(value); }
  bool has(std::string_view key) const { return values_.find(key) != values_.end(); }
  const Value* find(std::string_view key) const;

  // These throw std::logic_error when the key is absent or of another kind: the loader has validated
  // every fit against its model's spec, so that is a programming error, not bad input.
  double scalar(std::string_view key) const;
  Rgb rgb(std::string_view key) const;
  // An optional choice that is absent reads as its default (the first choice).
  std::string choice(std::string_view key, std::span<const ParamSpec> specs) const;

  const std::map<std::string, Value, std::less<>>& values() const { return values_; }
  bool operator==(const ParamSet&) const = default;

 private:
  std::map<std::string, Value, std::less<>> values_;
};

}  // namespace glossy
