// glossy.error and glossy.fit: the metrics E1 and E2 of Löw et al. 2012 and the fitter behind `glossy error`
// and `glossy fit` (docs/fitting.md), the same numbers for the same table.
#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "renderer/util/output_lock.h"
#include "materials/fitting/fitter.h"
#include "renderer/app/destination.h"
#include "renderer/app/fit_job.h"
#include "renderer/app/fit_output.h"
#include "renderer/python/brdf_bindings.h"

#include <pybind11/stl.h>

namespace glossy::python {

namespace {

struct PyFit {
  FitReport report;
  std::string table;  // the measured file the fit was made from
};

const PyMeasured& tableOf(const py::handle& table) {
  if (!py::isinstance<PyMeasured>(table))
    throw InputError("table: expected measured data from glossy.load_merl(), not " + std::string(py::str(py::type::of(table).attr("__name__"))));
  return table.cast<const PyMeasured&>();
}

// What `glossy fit -o` does, through the same code: the output checked first, then the fit put in as
// glossy's, beside a published one (removed only with replace), what it replaced said on stderr.
void saveFit(const PyFit& f, const std::string& path, bool replace) {
  app::checkOutputFile(path, "path", {".toml"}, app::Folder::Exist);
  const OutputLock lock(path, "path");
  const std::string replaced = app::writeGlossysFit(path, f.table, f.report.fit, replace);
  if (!replaced.empty()) py::module_::import("sys").attr("stderr").attr("write")("glossy: " + path + ": " + replaced + "\n");
}

}  // namespace

// glossy.fit_tables: `glossy fit --measured-dir` (renderer/app/fit_job.h), the same files.
static void bindFitBatch(py::module_& m) {
  m.def("fit_tables", [](const py::object& measuredDir, const py::object& outDir, const py::object& models, const py::object& metrics,
                         const py::object& shard, int starts, int maxIterations, int threads, bool replace) {
          return guarded([&] {
            app::FitBatchRequest r;
            r.measuredDir = pathText(measuredDir);
            r.outDir = pathText(outDir);
            r.outDirName = "out_dir", r.modelName = "models", r.metricName = "metrics";
            r.models = stringList(models, "models");
            r.metrics = stringList(metrics, "metrics");
            if (!shard.is_none()) r.shard = pathText(shard);
            r.settings.refinedStarts = int(checkedOption(app::options::kStarts, starts));
            r.settings.maxIterations = int(checkedOption(app::options::kMaxIterations, maxIterations));
            r.settings.threads = int(checkedOption(app::options::kThreads, threads));
            r.replace = replace;
            app::FitBatchRun run;
            {
              py::gil_scoped_release noGil;
              run = app::fitTables(r);
            }
            py::dict d;
            d["tables"] = run.tables, d["fits"] = run.fits, d["already_done"] = run.alreadyDone;
            return d;
          });
        }, py::arg("measured_dir"), py::arg("out_dir"), py::arg("models") = py::none(), py::arg("metrics") = py::none(),
        py::arg("shard") = py::none(), py::kw_only(), py::arg("starts") = 4, py::arg("max_iterations") = 200, py::arg("threads") = 0,
        py::arg("replace") = false, R"doc(
Fits every model (default: every fittable one) under every metric (default E1 and E2) to every table and
network in measured_dir, one material file per table in out_dir, as `glossy fit --measured-dir DIR
--out-dir OUT` does (the same files): fits this version already made with these settings are skipped, so
a call resumes; shard='i/N' fits one shard of a job array. Returns counts: tables, fits, already_done.
Runs without the GIL; it cannot be interrupted.
)doc");
}

void bindFitting(py::module_& m) {
  py::class_<PyFit, std::shared_ptr<PyFit>>(m, "Fit", "A fitted model: its parameters, its BRDF and the error E it reached.")
      .def_property_readonly("model", [](const PyFit& f) { return f.report.fit.id.model; })
      .def_property_readonly("metric", [](const PyFit& f) { return f.report.fit.id.metric; })
      .def_property_readonly("error", [](const PyFit& f) { return f.report.error; }, "E under the fit's metric.")
      .def_property_readonly("params", [](const PyFit& f) { return paramsDict(f.report.fit.params); })
      .def_property_readonly("brdf", [](const PyFit& f) {
             return std::make_shared<PyBrdf>(PyBrdf{makeBrdf(f.report.fit), f.report.fit.id.model,
                                                    f.report.fit.id.str() + " fitted to " + f.table, f.report.fit.params});
           })
      .def_property_readonly("start_errors", [](const PyFit& f) { return f.report.startErrors; },
                             "E each refined start reached, best scan point first.")
      .def_property_readonly("seconds", [](const PyFit& f) { return f.report.seconds; })
      .def("save", [](const PyFit& f, const py::object& path, bool replace) { guarded([&] { saveFit(f, pathText(path), replace); }); },
           py::arg("path"), py::kw_only(), py::arg("replace") = false,
           "Puts the fit into a material parameter file as `glossy fit -o` does: as MODEL:METRIC:glossy, beside the published "
           "fit of its model and metric (replace=True removes that one), replacing glossy's earlier one, the file's other fits "
           "kept; a new file is named and measured after the data fitted.")
      .def("__repr__", [](const PyFit& f) {
        return "<glossy.Fit " + f.report.fit.id.str() + " E=" + std::to_string(f.report.error) + ">";
      });

  m.def("error", [](const py::object& brdf, const py::object& table, const std::string& metric) {
          return guarded([&] {
            const PyMeasured& data = tableOf(table);
            const Metric which = parseMetric(metric, "metric");
            if (!py::isinstance<PyBrdf>(brdf)) throw InputError("brdf: expected a glossy.Brdf");
            const Brdf b = brdf.cast<const PyBrdf&>().brdf;
            py::gil_scoped_release noGil;
            return MetricData(*data.table, which).error(b);
          });
        }, py::arg("brdf"), py::arg("table"), py::arg("metric") = "E2", R"doc(
E of a BRDF against measured data under metric "E1" or "E2" (Löw et al. 2012, on glossy's direction grid;
docs/fitting.md): the figure `glossy error` prints.
)doc");

  m.def("fit", [](const py::object& table, const std::string& model, const std::string& metric, int starts, int maxIterations,
                  int threads) {
          return guarded([&] {
            const PyMeasured& data = tableOf(table);
            const Metric which = parseMetric(metric, "metric");
            requireFittable(model, "model");
            FitSettings settings;
            settings.refinedStarts = int(checkedOption(app::options::kStarts, starts));
            settings.maxIterations = int(checkedOption(app::options::kMaxIterations, maxIterations));
            settings.threads = int(checkedOption(app::options::kThreads, threads));
            auto out = std::make_shared<PyFit>();
            out->table = data.path;
            {
              py::gil_scoped_release noGil;
              const MetricData grid(*data.table, which);
              out->report = fitModel(grid, model, settings);
            }
            app::stampGlossysFit(out->report.fit, data.path);
            return out;
          });
        }, py::arg("table"), py::arg("model") = "cook-torrance", py::arg("metric") = "E2", py::kw_only(), py::arg("starts") = 4,
        py::arg("max_iterations") = 200, py::arg("threads") = 0, R"doc(
Fits an analytic model to measured data under "E1" or "E2", as `glossy fit` does (the same parameters for
the same table and settings, on any thread count): a coarse scan of the lobe's shape, then Levenberg-Marquardt
from the best `starts` widths. Returns a glossy.Fit. Runs without the GIL; it cannot be interrupted.
)doc");

  bindFitBatch(m);
}

}  // namespace glossy::python
