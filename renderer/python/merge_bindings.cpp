// glossy.merge_fits and glossy.merge_sheets: `glossy merge fits` and `glossy merge sheets`
// (renderer/app/merge_job.h) from Python, so the two write the same bytes.
#include "renderer/app/merge_job.h"
#include "renderer/python/module_support.h"

namespace glossy::python {

void bindMerging(py::module_& m) {
  m.def("merge_fits", [](const py::object& folder, const py::object& output, bool replace) {
          return guarded([&] {
            app::MergeFitsRequest r{pathText(folder), pathText(output), "output", replace};
            const app::MergeFitsResult done = app::mergeFits(r);
            py::dict d;
            d["fits"] = done.fits, d["materials"] = done.materials, d["replaced"] = done.replaced, d["unchanged"] = done.unchanged;
            d["files_written"] = done.filesWritten;
            return d;
          });
        }, py::arg("folder"), py::arg("output"), py::arg("replace") = false, R"doc(
Every fit of folder/NAME.toml (glossy fit --out-dir, one file per material) put into output/NAME.toml,
keeping the fits already there of other models and metrics: glossy's fit replaces glossy's earlier one;
a published fit never replaces a different published one unless replace=True. Everything is read and
checked before anything is written. Returns counts: fits, materials, replaced, unchanged, files_written.
As `glossy merge fits FOLDER -o OUTPUT [--replace]` (docs/cluster.md).
)doc");
  m.def("merge_sheets", [](const py::object& folder, const py::object& csv, const py::object& json) {
          return guarded([&] {
            app::MergeSheetsRequest r;
            r.sheetsDir = pathText(folder);
            if (!csv.is_none()) r.csv = pathText(csv);
            if (!json.is_none()) r.json = pathText(json);
            r.csvName = "csv", r.jsonName = "json";
            return app::mergeSheets(r).sheets;
          });
        }, py::arg("folder"), py::arg("csv") = py::none(), py::arg("json") = py::none(), R"doc(
Every sheet's figures in folder (glossy sheets -o FOLDER) in one table: a CSV row per panel and the
noise-floor row, and/or a JSON object per sheet. Returns the number of sheets. As `glossy merge sheets
FOLDER --csv CSV --json JSON`, the same bytes.
)doc");
}

}  // namespace glossy::python
