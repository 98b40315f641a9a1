// glossy.list_library: `glossy list` (renderer/app/list_job.h) from Python, as rows to compute with.
#include "materials/core/input_error.h"
#include "renderer/app/list_job.h"
#include "renderer/python/module_support.h"

namespace glossy::python {

void bindListing(py::module_& m) {
  m.def("list_library", [](const py::object& paths, const py::object& merlDir, const py::object& panels) {
          return guarded([&] {
            std::vector<std::string> p;
            if (!paths.is_none()) {
              if (py::isinstance<py::str>(paths)) throw InputError("paths: a list of files and folders, not one string");
              for (const py::handle& item : paths) p.push_back(pathText(item));
            }
            std::optional<std::string> columns;
            if (!panels.is_none()) {
              if (!py::isinstance<py::str>(panels)) throw InputError("panels: must be a string, a grid's name or a comma list of fits");
              columns = panels.cast<std::string>();
            }
            const app::Listing listing = app::listLibrary(p, merlDir.is_none() ? std::string() : pathText(merlDir), columns, "panels");
            py::list rows;
            for (const app::ListedFolder& folder : listing.folders)
              for (const app::ListedMaterial& mat : folder.materials) {
                py::dict d;
                d["database"] = folder.database, d["file"] = mat.file.string(), d["error"] = mat.error.empty() ? py::object(py::none()) : py::str(mat.error);
                d["material"] = mat.name, d["measured"] = mat.measured;
                py::dict albedo, others;
                for (size_t k = 0; k < listing.columns.size() && k < mat.albedo.size(); ++k)
                  albedo[py::str(listing.columns[k].fit)] = mat.albedo[k] ? py::object(py::float_(*mat.albedo[k])) : py::object(py::none());
                for (const auto& [id, value] : mat.otherFits) others[py::str(id)] = value;
                d["albedo"] = albedo, d["other_fits"] = others;
                rows.append(d);
              }
            return rows;
          });
        }, py::arg("paths") = py::none(), py::arg("merl_dir") = py::none(), py::arg("panels") = py::none(), R"doc(
The material files paths name (files and folders; None: the library), a dict per file: database (the
folder's, as its networks label it), file, error (why it could not be read, else None), material, measured
('found', 'network', 'missing' or '-'), albedo (each column's fit, MODEL:METRIC: its head-on directional
albedo, the mean of R, G, B, or None without that fit; the columns are the comparison grid's fits or those
panels names) and other_fits (the fits no column shows, by id). As `glossy list [PATHS] [--merl-dir]
[--panels]` prints them.
)doc");
}

}  // namespace glossy::python
