// glossy.Brdf and where BRDFs come from: a material file's fits (load_material), measured data (load_merl),
// a model and its parameters (make_brdf). eval, pdf and sample take NumPy arrays and loop in C++ without the
// GIL, in parallel for large arrays (each row is computed alone, so the result does not depend on it), and
// answer exactly what `glossy eval` and `glossy sample` print for the same rows.
#include "renderer/python/brdf_bindings.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/core/unit_direction.h"
#include "materials/models/registry.h"
#include "renderer/app/brdf_options.h"

#include <pybind11/stl.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <random>

namespace glossy::python {

namespace {

using InArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// An (N, 3) or (3,) array of float64 read in place (converted once when it is another type or layout); a
// (3,) array stands for the same row N times.
struct Rows {
  InArray array;
  const double* data = nullptr;
  size_t n = 0;
  bool single = false;
  size_t stride = 3;  // 0 for a single row

  Vec3 operator[](size_t i) const {
    const double* p = data + stride * i;
    return {p[0], p[1], p[2]};
  }
};

Rows rowsOf(const py::handle& value, const char* name) {
  Rows r;
  r.array = InArray::ensure(value);
  if (!r.array) {
    PyErr_Clear();
    throw InputError(formatted("%s: not an array of numbers", name));
  }
  const py::ssize_t nd = r.array.ndim();
  if (nd == 1 && r.array.shape(0) == 3) {
    r.single = true;
    r.n = 1;
    r.stride = 0;
  } else if (nd == 2 && r.array.shape(1) == 3) {
    r.n = size_t(r.array.shape(0));
  } else {
    const std::string shape =
        joined(std::vector<py::ssize_t>(r.array.shape(), r.array.shape() + nd), ", ", [](py::ssize_t n) { return std::to_string(n); });
    throw InputError(formatted("%s: expected shape (N, 3) or (3,), got (%s%s)", name, shape.c_str(), nd == 1 ? "," : ""));
  }
  r.data = r.array.data();
  return r;
}

// The rows two arguments share: equal counts, or one of them a single row.
size_t pairedRows(const Rows& a, const char* aName, const Rows& b, const char* bName) {
  if (a.single) return b.n;
  if (b.single || a.n == b.n) return a.n;
  throw InputError(formatted("%s and %s: %zu and %zu rows (give as many of each, or one row of either)", aName, bName, a.n, b.n));
}

static_assert(sizeof(Rgb) == 3 * sizeof(double), "an (N, 3) float64 array is N Rgb values");

// An output array of the given shape: `out` when it is one (float64, C-contiguous, writable, that shape), a
// new one when it is None.
py::array_t<double> outputArray(const py::object& out, std::vector<py::ssize_t> shape) {
  if (out.is_none()) return py::array_t<double>(shape);
  const auto a = py::array_t<double>::ensure(out);  // a view when out is float64 already
  const bool fits = a && py::isinstance<py::array_t<double>>(out) && a.ndim() == py::ssize_t(shape.size()) &&
                    std::equal(shape.begin(), shape.end(), a.shape()) && (a.flags() & py::array::c_style) && a.writeable();
  if (!fits) {
    PyErr_Clear();
    const std::string want = joined(shape, ", ", [](py::ssize_t n) { return std::to_string(n); });
    throw InputError("out: must be a writable C-contiguous float64 array of shape (" + want + (shape.size() == 1 ? ",)" : ")"));
  }
  return py::reinterpret_borrow<py::array_t<double>>(out);
}

// body(begin, end) over [0, n): in parallel on `threads` threads (0: all) when n is large enough to gain.
template <class Body>
void forRows(size_t n, int threads, const Body& body) {
  constexpr size_t kGrain = 8192;
  if (threads == 1 || n < 4 * kGrain) {
    body(size_t(0), n);
    return;
  }
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
  });
}

// The first row that failed a check, over all threads.
struct FirstBad {
  std::atomic<size_t> row{std::numeric_limits<size_t>::max()};
  void record(size_t i) {
    size_t seen = row.load();
    while (i < seen && !row.compare_exchange_weak(seen, i)) {
    }
  }
  bool any() const { return row.load() != std::numeric_limits<size_t>::max(); }
};

// A row read in place (rows are float64 triples, as Vec3 is) when it is a unit vector already, else its
// copy made unit in `copy`; null when it cannot be made one.
const Vec3* unitRow(const double* row, Vec3& copy) {
  const Vec3* d = reinterpret_cast<const Vec3*>(row);
  if (isUnitDirection(*d)) [[likely]]
    return d;
  copy = *d;
  return makeUnitDirection(copy) ? &copy : nullptr;
}

// body(i, ok, l, v) for every row i in [begin, end), l and v its directions made unit as glossy eval makes
// them (makeUnitDirection), ok false (and the row recorded) where either is zero or not finite.
template <class Body>
void forUnitPairs(const Rows& L, const Rows& V, size_t begin, size_t end, FirstBad& badL, FirstBad& badV, const Body& body) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double) && alignof(Vec3) == alignof(double));
  const double *l = L.data + L.stride * begin, *v = V.data + V.stride * begin;
  Vec3 copyL, copyV;
  for (size_t i = begin; i < end; ++i, l += L.stride, v += V.stride) {
    const Vec3 *unitL = unitRow(l, copyL), *unitV = unitRow(v, copyV);
    if (!unitL) [[unlikely]] badL.record(i);
    if (!unitV) [[unlikely]] badV.record(i);
    if (unitL && unitV) [[likely]]
      body(i, true, *unitL, *unitV);
    else
      body(i, false, Vec3(0.0), Vec3(0.0));
  }
}

void throwBadDirection(const FirstBad& badL, const FirstBad& badV, const Rows& L, const Rows& V) {
  // The lower row first, as a reader scanning the input would meet it.
  const bool l = badL.any() && (!badV.any() || badL.row <= badV.row);
  const size_t row = l ? badL.row.load() : badV.row.load();
  throw InputError(formatted("%s[%zu]: a direction is zero or not finite", l ? "L" : "V", (l ? L.single : V.single) ? 0 : row));
}

int checkedThreads(int threads) { return int(checkedOption(app::options::kThreads, threads)); }

// f(values, ok, l, v) for every pair of rows of L and V (forUnitPairs), writing the row's kWidth values into an
// array of shape (N, kWidth), or (N,) for one value: `out` when given.
template <size_t kWidth, class F>
py::array_t<double> pairRows(const py::handle& lArg, const py::handle& vArg, const py::object& out, int threads, const F& f) {
  checkedThreads(threads);
  const Rows L = rowsOf(lArg, "L"), V = rowsOf(vArg, "V");
  const size_t n = pairedRows(L, "L", V, "V");
  py::array_t<double> result = outputArray(out, kWidth == 1 ? std::vector{py::ssize_t(n)} : std::vector{py::ssize_t(n), py::ssize_t(kWidth)});
  double* values = result.mutable_data();
  FirstBad badL, badV;
  {
    py::gil_scoped_release noGil;
    forRows(n, threads, [&](size_t begin, size_t end) {
      forUnitPairs(L, V, begin, end, badL, badV, [&](size_t i, bool ok, const Vec3& l, const Vec3& v) { f(values + kWidth * i, ok, l, v); });
    });
  }
  if (badL.any() || badV.any()) throwBadDirection(badL, badV, L, V);
  return result;
}

py::array_t<double> evalRows(const Brdf& brdf, const py::handle& L, const py::handle& V, const py::object& out, int threads) {
  return pairRows<3>(L, V, out, threads, [&](double* rho, bool ok, const Vec3& l, const Vec3& v) {
    *reinterpret_cast<Rgb*>(rho) = ok ? eval(brdf, l, v) : Rgb(0.0);
  });
}

py::array_t<double> pdfRows(const Brdf& brdf, const py::handle& L, const py::handle& V, const py::object& out, int threads) {
  return pairRows<1>(L, V, out, threads, [&](double* density, bool ok, const Vec3& l, const Vec3& v) { *density = ok ? pdf(brdf, l, v) : 0.0; });
}

py::tuple sampleRows(const Brdf& brdf, const py::handle& vArg, const py::handle& uArg, int threads) {
  checkedThreads(threads);
  const Rows V = rowsOf(vArg, "V"), u = rowsOf(uArg, "u");
  const size_t n = pairedRows(V, "V", u, "u");
  py::array_t<double> L({py::ssize_t(n), py::ssize_t(3)}), density({py::ssize_t(n)}), weight({py::ssize_t(n), py::ssize_t(3)});
  double *l = L.mutable_data(), *p = density.mutable_data(), *w = weight.mutable_data();
  FirstBad badV, badU;
  {
    py::gil_scoped_release noGil;
    forRows(n, threads, [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) {
        Vec3 v = V[i];
        const Vec3 r = u[i];
        const bool okV = makeUnitDirection(v);
        const bool okU = r.x >= 0.0 && r.x < 1.0 && r.y >= 0.0 && r.y < 1.0 && r.z >= 0.0 && r.z < 1.0;
        if (!okV) badV.record(i);
        if (!okU) badU.record(i);
        const BrdfSample s = okV && okU ? sample(brdf, v, r.x, Vec2(r.y, r.z)) : BrdfSample{};
        // An invalid sample is all zeros, as glossy sample prints it.
        const bool valid = s.valid();
        l[3 * i] = valid ? s.L.x : 0.0, l[3 * i + 1] = valid ? s.L.y : 0.0, l[3 * i + 2] = valid ? s.L.z : 0.0;
        p[i] = valid ? s.pdf : 0.0;
        w[3 * i] = valid ? s.weight.r : 0.0, w[3 * i + 1] = valid ? s.weight.g : 0.0, w[3 * i + 2] = valid ? s.weight.b : 0.0;
      }
    });
  }
  if (badV.any() && (!badU.any() || badV.row <= badU.row))
    throw InputError(formatted("V[%zu]: a direction is zero or not finite", V.single ? size_t(0) : badV.row.load()));
  if (badU.any()) throw InputError(formatted("u[%zu]: the numbers must lie in [0, 1)", u.single ? size_t(0) : badU.row.load()));
  return py::make_tuple(L, density, weight);
}

PyBrdf brdfOfFit(const Fit& fit, const std::string& from) {
  return PyBrdf{makeBrdf(fit), fit.id.model, fit.id.str() + (from.empty() ? "" : " of " + from), fit.params};
}

// make_brdf's keywords as a fit of `model`, checked as a parameter file's are.
PyBrdf brdfFromKeywords(const std::string& model, const py::kwargs& kwargs) {
  const ModelInfo& info = requireModel(model, "make_brdf");
  Fit fit;
  fit.id = {std::string(info.name), "E2"};
  for (const auto& [key, value] : kwargs) {
    const std::string k = py::str(key);
    const std::string where = "make_brdf: " + model + ": " + k;
    if (py::isinstance<py::str>(value)) {
      fit.params.set(k, value.cast<std::string>());
    } else if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) {
      fit.params.set(k, value.cast<double>());
    } else {
      std::vector<double> v;
      try {
        v = value.cast<std::vector<double>>();
      } catch (const py::cast_error&) {
        throw InputError(where + ": expected a number, three numbers (R, G, B) or a string");
      }
      if (v.size() != 3) throw InputError(where + ": expected three numbers (R, G, B), got " + std::to_string(v.size()));
      fit.params.set(k, Rgb(v[0], v[1], v[2]));
    }
  }
  validateFit(fit, "make_brdf: " + model);
  return PyBrdf{makeBrdf(fit), std::string(info.name), std::string(info.name), fit.params};
}

const Fit& fitOf(const PyMaterial& m, const std::string& id) {
  const FitId fitId = FitId::parse(id, "fit");
  const Fit* fit = m.file.find(fitId);
  if (!fit) throw InputError(m.file.path.string() + ": has no " + fitId.str() + " fit");
  return *fit;
}

}  // namespace

py::dict paramsDict(const ParamSet& params) {
  py::dict d;
  for (const auto& [key, value] : params.values()) {
    if (const auto* x = std::get_if<double>(&value)) d[py::str(key)] = *x;
    else if (const auto* c = std::get_if<Rgb>(&value)) d[py::str(key)] = py::make_tuple(c->r, c->g, c->b);
    else d[py::str(key)] = std::get<std::string>(value);
  }
  return d;
}

// Brdf, MeasuredBrdf, Material, load_material, load_merl, make_brdf, models and uniforms, each defined once
// with its docstring: over 80 lines because it is one table of Python names read top to bottom, which a
// split would scatter.
void bindBrdfs(py::module_& m) {
  py::class_<PyBrdf, std::shared_ptr<PyBrdf>>(m, "Brdf", R"doc(
A BRDF: an analytic model with its parameters, or measured data.

Directions are in the local shading frame (normal = +z), L toward the light, V toward the viewer, as
float64 arrays of shape (N, 3); a (3,) array stands for the same direction in every row. Directions are
normalised here, as `glossy eval` does; a zero or non-finite one raises InputError naming its row.
Large arrays are processed in parallel without the GIL; the values do not depend on it.
)doc")
      .def("eval", [](const PyBrdf& b, const py::handle& L, const py::handle& V, const py::object& out, int threads) {
             return guarded([&] { return evalRows(b.brdf, L, V, out, threads); });
           },
           py::arg("L"), py::arg("V"), py::kw_only(), py::arg("out") = py::none(), py::arg("threads") = 0,
           R"doc(
BRDF values ρ(L, V) in 1/sr, shape (N, 3) (R, G, B): what `glossy eval` prints for the same rows.
Zero unless both directions are above the surface. `out`: an array of shape (N, 3) to write into.
)doc")
      .def("pdf", [](const PyBrdf& b, const py::handle& L, const py::handle& V, const py::object& out, int threads) {
             return guarded([&] { return pdfRows(b.brdf, L, V, out, threads); });
           },
           py::arg("L"), py::arg("V"), py::kw_only(), py::arg("out") = py::none(), py::arg("threads") = 0,
           R"doc(
The solid-angle density, shape (N,), with which sample() draws L given V (`glossy eval --pdf`).
)doc")
      .def("sample", [](const PyBrdf& b, const py::handle& V, const py::handle& u, int threads) {
             return guarded([&] { return sampleRows(b.brdf, V, u, threads); });
           },
           py::arg("V"), py::arg("u"), py::kw_only(), py::arg("threads") = 0,
           R"doc(
Directions drawn from the BRDF's sampler: returns (L (N, 3), pdf (N,), weight (N, 3)), weight = ρ cos θ_L / pdf.

u, shape (N, 3), holds three uniform numbers in [0, 1) per draw: the first picks the lobe, the other two
place the direction in it. An invalid sample (below the horizon, rejected) is a row of zeros. With
u = glossy.uniforms(N, seed) the rows equal `glossy sample -n N --seed seed` line for line.
)doc")
      .def_readonly("model", &PyBrdf::model, "The model's name as parameter files write it, or 'measured'.")
      .def_property_readonly("params", [](const PyBrdf& b) { return paramsDict(b.params); },
                             "The model's parameters: floats, (R, G, B) tuples and choices; empty for measured data.")
      .def("__repr__", [](const PyBrdf& b) { return "<glossy.Brdf " + b.description + ">"; });

  py::class_<PyMeasured, PyBrdf, std::shared_ptr<PyMeasured>>(m, "MeasuredBrdf", R"doc(
Measured data as a BRDF (a MERL table, or a Neural BRDF tabulated as one): eval() is the reference
nearest-bin lookup; sample() draws from the table's own tabulated density.
)doc")
      .def_readonly("path", &PyMeasured::path, "The file it was read from.")
      .def_readonly("label", &PyMeasured::label, "How sheets and images name it, e.g. 'MERL (NBRDF reconstruction) FILE'.")
      .def_property_readonly("invalid_bins", [](const PyMeasured& t) { return t.table->invalidBins(); },
                             "Bins with an unmeasured (negative) channel; they evaluate to 0.");

  py::class_<PyMaterial, std::shared_ptr<PyMaterial>>(m, "Material", R"doc(
A material parameter file: its name, its measured data's name and its fits, each named MODEL:METRIC.
)doc")
      .def_property_readonly("name", [](const PyMaterial& x) { return x.file.name; })
      .def_property_readonly("path", [](const PyMaterial& x) { return x.file.path.string(); })
      .def_property_readonly("measured", [](const PyMaterial& x) { return x.file.measured; },
                             "The measured data the file names (a MERL table or .nbrdf), or ''.")
      .def_property_readonly("fits", [](const PyMaterial& x) {
             std::vector<std::string> ids;
             for (const Fit& f : x.file.fits) ids.push_back(f.id.str());
             return ids;
           }, "The fits' names, MODEL:METRIC, in the comparison grid's order.")
      .def("brdf", [](const PyMaterial& x, const std::string& fit) {
             return guarded([&] { return std::make_shared<PyBrdf>(brdfOfFit(fitOf(x, fit), x.file.name)); });
           }, py::arg("fit"), "The BRDF of one fit, e.g. material.brdf('cook-torrance:E2').")
      .def("params", [](const PyMaterial& x, const std::string& fit) { return guarded([&] { return paramsDict(fitOf(x, fit).params); }); },
           py::arg("fit"), "One fit's parameters as a dict.")
      .def("__repr__", [](const PyMaterial& x) { return "<glossy.Material " + x.file.name + ": " + std::to_string(x.file.fits.size()) + " fits>"; });

  m.def("load_material", [](const py::object& path) {
          return guarded([&] { return std::make_shared<PyMaterial>(PyMaterial{loadMaterialFile(pathText(path))}); });
        }, py::arg("path"), R"doc(
Reads a material parameter file (TOML): glossy.load_material("materials/library/merl/alum-bronze.toml").
Raises InputError, with the message `glossy` prints, naming the file, line and key for anything malformed.
)doc");
  m.def("load_merl", [](const py::object& path, const py::object& merlDir) {
          return guarded([&] {
            const std::string dir = merlDir.is_none() ? std::string() : pathText(merlDir);
            checkMerlDirs(dir, "merl_dir");
            const std::filesystem::path file = app::findMeasured(pathText(path), dir);
            auto table = app::loadMeasured(file);
            PyMeasured out;
            {
              py::gil_scoped_release noGil;  // the sampling tables take a moment
              out.brdf = Measured{table};
            }
            out.model = "measured";
            out.description = "measured " + file.string();
            out.table = std::move(table);
            out.path = file.string();
            out.label = app::measuredLabel(file);
            return std::make_shared<PyMeasured>(std::move(out));
          });
        }, py::arg("path"), py::arg("merl_dir") = py::none(), R"doc(
Reads measured data: a MERL table (NAME.binary or NAME.binary.xz) or a Neural BRDF (NAME.nbrdf).
A relative name not found as given is looked for under merl_dir, then $GLOSSY_MERL_DIR, as `--measured`
is. Unmeasured bins are reported as a GlossyWarning.
)doc");
  m.def("make_brdf", [](const std::string& model, const py::kwargs& params) {
          return guarded([&] { return std::make_shared<PyBrdf>(brdfFromKeywords(model, params)); });
        }, py::arg("model"), R"doc(
A model with the given parameters, checked as a parameter file's are (docs/materials.md lists each
model's keys and ranges): glossy.make_brdf("cook-torrance", kd=(0.1, 0.1, 0.1), ks=(0.5, 0.5, 0.5), m=0.2, eta=1.5).
RGB parameters take three numbers; choices take a string.
)doc");
  m.def("models", [] {
          std::vector<std::string> names;
          for (const ModelInfo& info : analyticModels()) names.emplace_back(info.name);
          return names;
        }, "The analytic models' names, in the comparison grid's order.");
  m.def("uniforms", [](long long n, uint64_t seed) {
          checkedOption(app::options::kSamples, double(n));
          py::array_t<double> u({py::ssize_t(n), py::ssize_t(3)});
          double* p = u.mutable_data();
          {
            py::gil_scoped_release noGil;
            // glossy sample's numbers: three per draw from one 64-bit Mersenne Twister, in this order.
            std::mt19937_64 rng(seed);
            std::uniform_real_distribution<double> uniform(0.0, 1.0);
            for (long long i = 0; i < 3 * n; ++i) p[i] = uniform(rng);
          }
          return u;
        }, py::arg("n"), py::arg("seed") = 0, R"doc(
The uniform numbers `glossy sample --seed seed` draws, shape (n, 3): pass them to Brdf.sample().
)doc");
}

}  // namespace glossy::python
