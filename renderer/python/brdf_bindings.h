// The Python objects behind glossy.Brdf, glossy.MeasuredBrdf and glossy.Material, which the fitting and
// rendering bindings take as arguments too.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/params/material_file.h"
#include "renderer/python/module_support.h"

#include <memory>
#include <string>

namespace glossy::python {

struct PyBrdf {
  PyBrdf() = default;
  PyBrdf(Brdf b, std::string m, std::string d, ParamSet p)
      : brdf(std::move(b)), model(std::move(m)), description(std::move(d)), params(std::move(p)) {}
  virtual ~PyBrdf() = default;

  Brdf brdf;
  std::string model;        // registry name, or "measured"
  std::string description;  // for repr() and image metadata: "cook-torrance:E2 of alum-bronze"
  ParamSet params;          // empty for measured data
};

struct PyMeasured : PyBrdf {
  std::shared_ptr<const MerlTable> table;
  std::string path, label;
};

struct PyMaterial {
  MaterialFile file;
};

// A fit's parameters as Python values: floats, (R, G, B) tuples and choices.
py::dict paramsDict(const ParamSet& params);

}  // namespace glossy::python
