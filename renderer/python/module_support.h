// What the binding files share: each adds its part of the module (bind*), calls into the library the way
// the command line does (guarded: InputError becomes glossy.InputError with the command line's message,
// the notes the CLI prints become Python warnings), and checks keyword arguments as the CLI checks options.
#pragma once

#include "renderer/util/notes.h"
#include "materials/core/types.h"
#include "renderer/app/option_specs.h"
#include "renderer/image/exr_image.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace glossy::python {

namespace py = pybind11;

void bindBrdfs(py::module_& m);
void bindFitting(py::module_& m);
void bindImages(py::module_& m);
void bindMerging(py::module_& m);
void bindReports(py::module_& m);
void bindPlots(py::module_& m);
void bindListing(py::module_& m);
void bindRendering(py::module_& m);
void bindStudies(py::module_& m);

// Hands the library's queued notes to Python as warnings, glossy.GlossyWarning (needs the GIL).
void warnNotes();

// A library call as the command line makes it: what loading noted is kept only when the input proved good.
template <class F>
auto guarded(F&& f) {
  try {
    if constexpr (std::is_void_v<decltype(f())>) {
      f();
      warnNotes();
    } else {
      auto result = f();
      warnNotes();
      return result;
    }
  } catch (...) {
    discardNotes();
    throw;
  }
}

// A keyword of the option table (renderer/app/option_specs.h) checked as the command line checks the option,
// in its words: "max_depth: must be a whole number in [1, 1000], not '0'". `name`: what the message calls it
// when not its keyword ("size: width").
double checkedOption(const app::OptionSpec& spec, double value, const std::string& name = "");

// Values as a C-ordered float32 array of `shape` that owns them: no copy.
py::array_t<float> floatArray(std::vector<float>&& values, std::vector<py::ssize_t> shape);

// An image as a float32 array (height, width, 3) that owns the pixels it was given: no copy.
py::array_t<float> imageArray(RgbImage&& image);

// A keyword given as a list of strings (None: empty), in the words of `name`: "figures: a list, not one
// string" (Python would otherwise iterate a string's characters).
std::vector<std::string> stringList(const py::object& list, const std::string& name);

// A path argument: str or os.PathLike, as the text the command line would have been given.
std::string pathText(const py::handle& path);

}  // namespace glossy::python
