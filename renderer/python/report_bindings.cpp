// glossy.report: `glossy report` (renderer/app/report_job.h) from Python, the same site.
#include "renderer/app/report_job.h"
#include "renderer/python/module_support.h"

namespace glossy::python {

void bindReports(py::module_& m) {
  m.def("report", [](const py::object& sheets, const py::object& output, const py::object& plots, const py::object& plotKinds,
                     bool plotData) {
          return guarded([&] {
            report::ReportOptions o;
            o.sheetsDir = pathText(sheets);
            o.site = pathText(output);
            if (!plots.is_none()) o.plotsDir = pathText(plots);
            o.plotKinds = stringList(plotKinds, "plot_kinds");
            o.plotKindsName = "plot_kinds";
            o.plotData = plotData;
            const report::ReportResult r = app::makeReport(o, "output");
            py::dict d;
            d["sheets"] = r.sheets, d["materials"] = r.materials.size(), d["images"] = r.images, d["plots"] = r.plots;
            return d;
          });
        }, py::arg("sheets"), py::arg("output"), py::arg("plots") = py::none(), py::arg("plot_kinds") = py::none(),
        py::arg("plot_data") = false, R"doc(
A static, offline HTML site of a folder of sheets (glossy sheets) or of a study's output folder, with the
plots of glossy plot when plots names their folder: as `glossy report SHEETS PLOTS -o OUTPUT
[--plot-kinds ...] [--plot-data]` (docs/report.md), the same site. Returns counts: sheets, materials,
images, plots.
)doc");
}

}  // namespace glossy::python
