#include "materials/params/param_set.h"

#include <stdexcept>

namespace glossy {

std::string_view describeBound(ParamBound bound) {
  switch (bound) {
    case ParamBound::None: return "any finite value";
    case ParamBound::NonNegative: return ">= 0";
    case ParamBound::Positive: return "> 0";
    case ParamBound::AboveOne: return "> 1";
  }
  return "";
}

bool satisfiesBound(double value, ParamBound bound) {
  switch (bound) {
    case ParamBound::None: return true;
    case ParamBound::NonNegative: return value >= 0.0;
    case ParamBound::Positive: return value > 0.0;
    case ParamBound::AboveOne: return value > 1.0;
  }
  return false;
}

const ParamSet::Value* ParamSet::find(std::string_view key) const {
  auto it = values_.find(key);
  return it == values_.end() ? nullptr : &it->second;
}

double ParamSet::scalar(std::string_view key) const {
  const Value* v = find(key);
  if (!v || !std::holds_alternative<double>(*v)) throw std::logic_error("no scalar parameter " + std::string(key));
  return std::get<double>(*v);
}

Rgb ParamSet::rgb(std::string_view key) const {
  const Value* v = find(key);
  if (!v || !std::holds_alternative<Rgb>(*v)) throw std::logic_error("no RGB parameter " + std::string(key));
  return std::get<Rgb>(*v);
}

std::string ParamSet::choice(std::string_view key, std::span<const ParamSpec> specs) const {
  if (const Value* v = find(key)) {
    if (!std::holds_alternative<std::string>(*v)) throw std::logic_error("no choice parameter " + std::string(key));
    return std::get<std::string>(*v);
  }
  for (const ParamSpec& s : specs)
    if (s.key == key && !s.choices.empty()) return std::string(s.choices.front());
  throw std::logic_error("no choice parameter " + std::string(key));
}

}  // namespace glossy
