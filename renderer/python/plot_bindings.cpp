// glossy.plot: `glossy plot` (renderer/app/plot_job.h) from Python, the same files.
#include "materials/core/input_error.h"
#include "renderer/app/plot_job.h"
#include "renderer/python/module_support.h"

namespace glossy::python {

void bindPlots(py::module_& m) {
  m.def("plot", [](const py::object& material, const py::object& output, const py::object& measured, const py::object& merlDir,
                   const std::string& channel, const py::object& panels, const py::object& figures, int decades,
                   const std::string& polarScale) {
          return guarded([&] {
            app::PlotRequest r;
            r.material = pathText(material);
            r.out = pathText(output);
            r.outName = "output";
            r.panelsName = "panels";
            r.channelName = "channel", r.polarScaleName = "polar_scale", r.figuresName = "figures", r.decadesName = "decades";
            if (!measured.is_none()) r.measured = pathText(measured);
            if (!merlDir.is_none()) r.merlDir = pathText(merlDir);
            r.channel = channel;
            r.polarScale = polarScale;
            r.decades = decades;
            if (!panels.is_none()) {
              if (!py::isinstance<py::str>(panels)) throw InputError("panels: must be a string, a grid's name or a comma list of fits");
              r.panels = panels.cast<std::string>();
            }
            r.figures = stringList(figures, "figures");
            const app::PlotRun run = app::makePlots(r);
            return run.figures;
          });
        }, py::arg("material"), py::arg("output"), py::arg("measured") = py::none(), py::arg("merl_dir") = py::none(),
        py::arg("channel") = "luminance", py::arg("panels") = py::none(), py::arg("figures") = py::none(), py::arg("decades") = 0,
        py::arg("polar_scale") = "log", R"doc(
A material's fits and measured data as figures in output (θ_h slices, image slices with the log-ratio to
the measured data, directional albedo, in-plane polar lobes; SVG, PNG with rsvg-convert, CSV, indexed by
plots.json): as `glossy plot --material MATERIAL -o OUTPUT` with --measured, --merl-dir, --channel (R, G, B,
luminance), --panels, --figures (theta_h, image_slice, albedo, polar), --decades (1-20; 0: to every curve's
floor) and --polar-scale (log, linear) (docs/plots.md), the same files. Returns the number of figures.
)doc");
}

}  // namespace glossy::python
