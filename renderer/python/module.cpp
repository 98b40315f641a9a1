// The Python module `glossy` (its compiled part, glossy._core; the package is renderer/python/glossy/):
// the models, measured data, fitting and rendering on NumPy arrays. docs/python.md shows it at work.
#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "materials/core/text.h"
#include "renderer/python/module_support.h"
#include "renderer/util/data_dir.h"

#include <cmath>

namespace glossy::python {

namespace {

PyObject* gWarning = nullptr;

}  // namespace

void warnNotes() {
  for (const std::string& line : takeNotes())
    if (PyErr_WarnEx(gWarning, line.c_str(), 2) != 0) throw py::error_already_set();
}

double checkedOption(const app::OptionSpec& spec, double value, const std::string& name) {
  if (!spec.accepts(value))
    throw InputError((name.empty() ? spec.keyword() : name) + ": " +
                     spec.refusal(spec.whole && value == std::floor(value) && std::abs(value) < 1e18 ? formatted("%lld", (long long)value)
                                                                                                   : formatted("%g", value)));
  return value;
}

py::array_t<float> floatArray(std::vector<float>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<float>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<float>*>(p); });
  return py::array_t<float>(std::move(shape), owned->data(), owner);
}

py::array_t<float> imageArray(RgbImage&& image) {
  return floatArray(std::move(image.pixels), {py::ssize_t(image.height), py::ssize_t(image.width), 3});
}

std::vector<std::string> stringList(const py::object& list, const std::string& name) {
  std::vector<std::string> out;
  if (list.is_none()) return out;
  if (py::isinstance<py::str>(list)) throw InputError(name + ": a list, not one string");
  for (const py::handle& item : list) {
    if (!py::isinstance<py::str>(item)) throw InputError(name + ": each must be a string");
    out.push_back(item.cast<std::string>());
  }
  return out;
}

std::string pathText(const py::handle& path) {
  if (py::isinstance<py::str>(path)) return path.cast<std::string>();
  const py::object fspath = py::module_::import("os").attr("fspath");
  const py::object text = fspath(path);  // TypeError for anything that is not a path
  if (!py::isinstance<py::str>(text)) throw py::type_error("a path must be str or os.PathLike of str, not bytes");
  return text.cast<std::string>();
}

}  // namespace glossy::python

PYBIND11_MODULE(_core, m) {
  namespace py = pybind11;
  using namespace glossy::python;
  m.doc() = "glossy's compiled core; use the package `glossy`, which re-exports it.";
  glossy::keepNotesForTaking();  // notes become warnings (warnNotes), never lines on stderr
  m.attr("__version__") = GLOSSY_VERSION;
  m.attr("_pybind11_version") = py::make_tuple(PYBIND11_VERSION_MAJOR, PYBIND11_VERSION_MINOR, PYBIND11_VERSION_PATCH);

  // Bad input: the command line's one-line message, which names the file or the argument.
  static py::exception<glossy::InputError> inputError(m, "InputError", PyExc_ValueError);
  inputError.doc() = "Bad input: a missing or malformed file, or an argument out of range. The message is the line "
                     "`glossy` prints for the same input, naming the file or the argument.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const glossy::InputError& e) {
      PyErr_SetString(inputError.ptr(), e.what());
    }
  });
  static py::exception<void> warning(m, "GlossyWarning", PyExc_UserWarning);
  warning.doc() = "What `glossy` notes on stderr while it loads input, e.g. a MERL table's unmeasured bins.";
  gWarning = warning.ptr();

  m.def("_safe_line", [](const std::string& text, size_t maxCharacters) { return glossy::safeLine(text, maxCharacters); },
        py::arg("text"), py::arg("max_characters") = 1000,
        "A message's one safe line as the library writes it (materials/core/text.h: safeLine).");
  m.def("_set_data_dir", [](const std::string& dir) { glossy::setDataDir(dir); },
        "Where the default scene and the material library are (the wheel's glossy/data).");
  m.def("_option_specs", [] {  // the table the keywords are checked by, for the tests
    py::list specs;
    for (const auto* o : glossy::app::optionSpecs())
      specs.append(py::dict(py::arg("keyword") = o->keyword(), py::arg("commands") = o->commands, py::arg("whole") = o->whole, py::arg("lo") = o->lo,
                            py::arg("hi") = o->hi, py::arg("lo_open") = o->loOpen, py::arg("range") = o->range(), py::arg("default") = o->fallback));
    return specs;
  });
  bindBrdfs(m);
  bindFitting(m);
  bindImages(m);
  bindMerging(m);
  bindReports(m);
  bindPlots(m);
  bindListing(m);
  bindRendering(m);
  bindStudies(m);
}
