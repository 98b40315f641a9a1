#include "materials/models/param_set.h"

#include "materials/core/text.h"

#include <stdexcept>

namespace glossy {

std::string describeRange(ParamRange range) {
  return formatted("in [%.10g, %.10g]", range.lo, range.hi);
}

bool inRange(double value, ParamRange range) { return value >= range.lo && value <= range.hi; }

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
