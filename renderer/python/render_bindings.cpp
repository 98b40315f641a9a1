// glossy.render, glossy.sheet and glossy.read_exr: the jobs behind `glossy render` and `glossy sheet`
// (renderer/app/render_job.h, sheet_job.h), run so that Ctrl-C and a progress callback work
// (background_job.h), with their images as float32 arrays that own or view the renderer's pixels.
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/app/destination.h"
#include "renderer/app/image_memory.h"
#include "renderer/app/option_specs.h"
#include "renderer/app/render_job.h"
#include "renderer/app/sheet_job.h"
#include "renderer/python/background_job.h"
#include "renderer/python/brdf_bindings.h"

#include <pybind11/stl.h>

#include <algorithm>

namespace glossy::python {

namespace {

// Python's own TypeError for a keyword the function does not take: a typo must not pass unnoticed.
void checkKeywords(const char* function, const py::kwargs& given, std::initializer_list<const char*> known) {
  for (const auto& [key, value] : given) {
    const std::string k = py::str(key);
    if (std::none_of(known.begin(), known.end(), [&](const char* name) { return k == name; }))
      throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + k + "'");
  }
}

// value as T, or InputError `message` (a str where numbers belong, and the like).
template <class T>
T castOr(const py::handle& value, const std::string& message) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw InputError(message);
  }
}

// A keyword's value when it was given (and is not None).
std::optional<py::object> given(const py::kwargs& a, const char* key) {
  if (!a.contains(key) || a[key].is_none()) return std::nullopt;
  return py::reinterpret_borrow<py::object>(a[key]);
}
// An option of the table as a keyword (max_depth for --max-depth), checked as the command line checks it.
std::optional<double> optionArg(const py::kwargs& a, const app::OptionSpec& spec) {
  const std::string key = spec.keyword();
  const auto v = given(a, key.c_str());
  if (!v) return std::nullopt;
  return checkedOption(spec, spec.whole ? double(castOr<long long>(*v, key + ": must be a whole number"))
                                        : castOr<double>(*v, key + ": must be a number"));
}
bool flagArg(const py::kwargs& a, const char* key) {
  const auto v = given(a, key);
  return v && castOr<bool>(*v, std::string(key) + ": must be True or False");
}

// The number keywords of render or sheet, as their command's options (size stands for width and height).
void numberKeywords(const py::kwargs& a, const std::vector<app::OptionField>& fields) {
  for (const app::OptionField& f : fields)
    if (f.spec->name != "width" && f.spec->name != "height")
      if (const auto v = optionArg(a, *f.spec)) f.set(*v);
}

std::string optionalPath(const py::object& path) { return path.is_none() ? std::string() : pathText(path); }

// The scene keywords as the command line's scene options (their messages name --env-constant and so on).
app::SceneOptions sceneOptions(const py::kwargs& a) {
  const auto text = [&](const char* key) { return given(a, key) ? pathText(*given(a, key)) : std::string(); };
  app::SceneOptions o;
  o.scene = text("scene");
  o.camera = given(a, "camera") ? castOr<std::string>(*given(a, "camera"), "camera: must be a string") : std::string();
  o.env = text("env");
  if (const auto radiance = given(a, "env_constant")) {
    const py::object& envConstant = *radiance;
    std::vector<double> v;
    if (py::isinstance<py::float_>(envConstant) || py::isinstance<py::int_>(envConstant)) v = {envConstant.cast<double>()};
    else v = castOr<std::vector<double>>(envConstant, "env_constant: expected a radiance or (R, G, B)");
    for (double x : v) o.envConstant += (o.envConstant.empty() ? "" : ",") + formatted("%.17g", x);
    if (v.empty()) o.envConstant = "[]";
  }
  if (!o.env.empty() && !o.envConstant.empty()) throw InputError("env and env_constant: give one of them");
  o.envRotate = optionArg(a, app::options::kEnvRotate).value_or(0.0);
  return o;
}

// size=None (the default), N, or (width, height).
std::pair<int, int> sizeOf(const py::object& size, const app::OptionSpec& width, const app::OptionSpec& height) {
  if (size.is_none()) return {int(width.fallback), int(height.fallback)};
  long long w, h;
  if (py::isinstance<py::int_>(size)) {
    w = h = castOr<long long>(size, "size: must be a whole number");
  } else {
    const auto wh = castOr<std::vector<long long>>(size, "size: expected N or (width, height)");
    if (wh.size() != 2) throw InputError("size: expected N or (width, height)");
    w = wh[0], h = wh[1];
  }
  return {int(checkedOption(width, double(w), "size: width")), int(checkedOption(height, double(h), "size: height"))};
}

py::array_t<float> renderArray(const py::kwargs& a) {
  checkKeywords("render", a, {"scene", "material", "fit", "measured", "brdf", "merl_dir", "camera", "env", "env_constant",
                              "env_rotate", "spp", "size", "seed", "threads", "max_depth", "light_samples", "brdf_sampling",
                              "reference", "progress", "output", "half"});
  auto get = [&](const char* key) { return given(a, key).value_or(py::none()); };
  app::RenderJob job;
  job.scene = sceneOptions(a);
  const py::object material = get("material"), fit = get("fit"), measured = get("measured"), brdf = get("brdf");
  if (!brdf.is_none() && (!material.is_none() || !measured.is_none()))
    throw InputError("brdf: give a brdf, a material and its fit, or measured data: one of them");
  if (!material.is_none() && !measured.is_none()) throw InputError("material and measured: give one of them");
  if (material.is_none() != fit.is_none()) throw InputError("material and fit: give both (fit = 'MODEL:METRIC') or neither");
  if (!material.is_none())
    job.material = py::isinstance<PyMaterial>(material) ? material.cast<const PyMaterial&>().file.path.string() : pathText(material);
  if (!fit.is_none()) job.fit = castOr<std::string>(fit, "fit: must be a string, MODEL:METRIC");
  job.measured = optionalPath(measured);
  job.merlDir = optionalPath(get("merl_dir"));
  checkMerlDirs(job.merlDir, "merl_dir");  // as every command's --merl-dir: a folder, or refused
  if (!brdf.is_none()) {
    if (!py::isinstance<PyBrdf>(brdf)) throw InputError("brdf: expected a glossy.Brdf");
    const PyBrdf& b = brdf.cast<const PyBrdf&>();
    Fit fitted;  // its choices go into the metadata, as a fit's from a file do
    fitted.id.model = b.model, fitted.params = b.params;
    job.brdf = BrdfChoice{b.brdf, b.description, b.model, fitted};
  }
  RenderSettings& s = job.settings;
  std::tie(s.width, s.height) = sizeOf(get("size"), app::options::kWidth, app::options::kHeight);
  numberKeywords(a, app::renderOptionFields(s));
  if (!get("brdf_sampling").is_none()) {
    job.brdfSampling = castOr<std::string>(get("brdf_sampling"), "brdf_sampling: must be a string");
    if (job.brdfSampling != "lobe" && job.brdfSampling != "cosine")
      throw InputError("brdf_sampling: must be 'lobe' or 'cosine', not '" + shortened(job.brdfSampling) + "'");
  }
  s.reference = flagArg(a, "reference");
  s.progress = false;
  const std::string output = optionalPath(get("output"));
  const bool half = flagArg(a, "half");
  if (!output.empty()) app::checkOutputFile(output, "output", {".exr"}, app::Folder::Create);
  app::checkImageMemory(s.width, s.height, 1, app::kRenderBytesPerPixel);

  JobControl control;
  s.control = &control;
  app::RenderedImage r = runInterruptible(control, get("progress"), [&] { return app::renderImage(job); });
  if (!output.empty()) {
    if (const std::filesystem::path out = output; out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    writeExr(output, r.image, r.metadata, half ? PixelType::Half : PixelType::Float);
  }
  return imageArray(std::move(r.image));
}

struct PySheet {
  std::shared_ptr<const app::Stage> stage;
  app::SheetJob job;
  app::MadeSheet made;
};

// A float32 view of pixels PySheet holds: no copy, and read-only, for save() writes what they hold.
py::array view(const py::object& owner, const float* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides) {
  py::array a(py::dtype::of<float>(), shape, strides, data, owner);
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

py::object optionalNumber(bool available, double value) { return available ? py::object(py::float_(value)) : py::object(py::none()); }
py::object optionalInterval(bool available, const Interval& i) {
  return available ? py::object(py::make_tuple(i.lo, i.hi)) : py::object(py::none());
}

py::dict panelFigures(const Sheet& sheet, const PanelRender& p) {
  const PanelFigures& f = p.figures;
  py::dict d;
  d["label"] = p.panel.label;
  d["fit"] = p.panel.fit.empty() ? std::string("measured") : p.panel.fit;
  d["colour"] = p.panel.colour;
  d["empty"] = p.empty;
  d["note"] = p.note;
  d["spp"] = p.empty ? 0 : sheet.spp;
  d["params"] = p.params;
  d["E1"] = optionalNumber(p.brdfE1 >= 0.0, p.brdfE1);
  d["E2"] = optionalNumber(p.brdfE2 >= 0.0, p.brdfE2);
  d["relative_rmse"] = optionalNumber(f.available, f.relativeRmse);
  d["relative_rmse_ci"] = optionalInterval(f.hasCi, f.relativeRmseCi);
  d["relative_rmse_clamped"] = f.available && f.clamped;
  d["relative_rmse_noisy"] = optionalNumber(f.compared, f.noisyRelativeRmse);
  d["luminance_ratio"] = optionalNumber(f.compared, f.luminanceRatio);
  d["luminance_ratio_ci"] = optionalInterval(f.hasCi, f.luminanceRatioCi);
  d["flip"] = optionalNumber(p.maps.available, p.maps.flip);
  d["flip_ci"] = optionalInterval(p.maps.available && p.maps.hasCi, p.maps.flipCi);
  d["delta_e_itp"] = optionalNumber(p.maps.available, p.maps.deltaEItp);
  d["delta_e_itp_ci"] = optionalInterval(p.maps.available && p.maps.hasCi, p.maps.deltaEItpCi);
  d["ssim"] = optionalNumber(p.maps.available, p.maps.ssim);
  d["ssim_ci"] = optionalInterval(p.maps.available && p.maps.hasCi, p.maps.ssimCi);
  return d;
}

std::shared_ptr<PySheet> renderSheetOf(const py::kwargs& a) {
  checkKeywords("sheet", a, {"material", "measured", "merl_dir", "scene", "camera", "env", "env_constant", "env_rotate", "spp",
                             "size", "time", "target_error", "seed", "threads", "max_depth", "light_samples", "exposure", "half",
                             "panels", "progress", "output"});
  auto get = [&](const char* key) { return given(a, key).value_or(py::none()); };
  auto sheet = std::make_shared<PySheet>();
  app::SheetJob& job = sheet->job;
  job.scene = sceneOptions(a);
  const py::object material = get("material");
  if (material.is_none()) throw InputError("material: a material file (or glossy.Material) is required");
  const std::string materialPath =
      py::isinstance<PyMaterial>(material) ? material.cast<const PyMaterial&>().file.path.string() : pathText(material);
  const std::string measured = optionalPath(get("measured"));
  job.merlDir = optionalPath(get("merl_dir"));
  checkMerlDirs(job.merlDir, "merl_dir");  // as every command's --merl-dir: a folder, or refused
  SheetSettings& s = job.settings;
  std::tie(s.width, s.height) = sizeOf(get("size"), app::options::kSheetWidth, app::options::kSheetHeight);
  numberKeywords(a, app::sheetOptionFields(job));
  // As glossy sheet: --time renders until it is spent, --target-error until it is met or the default cap;
  // spp caps them when given.
  app::applyPassLimits(s, given(a, "spp").has_value());
  job.half = flagArg(a, "half");
  if (const py::object panels = get("panels"); !panels.is_none())
    s.panels = parsePanels(castOr<std::string>(panels, "panels: must be a string, a comma list of measured and MODEL:METRIC"), "panels");
  s.progress = false;
  const std::string output = optionalPath(get("output"));
  if (!output.empty()) app::checkOutputFile(output, "output", {".exr"}, app::Folder::Create);
  app::checkImageMemory(s.width, s.height, int(s.panels.size()), app::kSheetBytesPerPanelPixel);

  JobControl control;
  s.control = &control;
  runInterruptible(control, get("progress"), [&] {
    sheet->stage = std::make_shared<const app::Stage>(job.scene, double(s.width) / double(s.height));
    sheet->made = app::makeMaterialSheet(*sheet->stage, materialPath, job, measured);
    return 0;
  });
  s.control = nullptr;
  if (!output.empty()) app::writeSheetFiles(sheet->made, *sheet->stage, job, output);
  return sheet;
}

}  // namespace

// render, Sheet, sheet, comparison_grid and read_exr, each defined once with its docstring: over 80 lines
// because it is one table of Python names read top to bottom, which a split would scatter.
void bindRendering(py::module_& m) {
  m.def("render", [](const py::kwargs& a) { return guarded([&] { return renderArray(a); }); }, R"doc(
render(*, scene=None, material=None, fit=None, measured=None, brdf=None, merl_dir=None, camera=None,
       env=None, env_constant=None, env_rotate=0.0, spp=64, size=(512, 512), seed=0, threads=0,
       max_depth=8, light_samples=4, brdf_sampling="lobe", reference=False, progress=None,
       output=None, half=False) -> numpy.ndarray

Renders a glTF scene as `glossy render` does and returns the image, float32 of shape (height, width, 3),
linear Rec. 709: for the same arguments and thread count, the image `glossy render` writes, bit for bit.

The object's BRDF: material (a parameter file or glossy.Material) with fit ("MODEL:METRIC"), measured
data (a MERL table or .nbrdf), or any glossy.Brdf (brdf); none: the scene's own bindings. scene: .gltf
or .glb (default: the material-preview scene). env: a lat-long .exr/.hdr; env_constant: a radiance or
(R, G, B); neither: the built-in sky. size: N or (width, height).

reference: render with the reference path tracer (plain one-path code, `glossy render --reference`): the same
image in expectation, noisier and slower. progress: callable(done, total), called with the tiles rendered so far. Ctrl-C stops the render and
raises KeyboardInterrupt; an exception raised by progress stops it too. output: also write the EXR.
)doc");

  py::class_<PySheet, std::shared_ptr<PySheet>>(m, "Sheet", R"doc(
A material's comparison sheet (glossy.sheet()): its panels side by side (by default Measured | Microfacet E2 |
Smooth E2 | AS E1 | AS E2 | CT E1 | CT E2), and each model's error figures against the measured panel.
)doc")
      .def_property_readonly("image", [](const py::object& self) {
             const Sheet& s = self.cast<const PySheet&>().made.sheet;
             const py::ssize_t w = s.grid.width, f = sizeof(float);
             return view(self, s.grid.pixels.data(), {s.grid.height, w, 3}, {3 * w * f, 3 * f, f});
           }, "The panels side by side, float32 (height, panels × width, 3); read-only.")
      .def_property_readonly("panels", [](const py::object& self) {
             const Sheet& s = self.cast<const PySheet&>().made.sheet;
             const py::ssize_t gw = s.grid.width, w = s.panels.front().image.width, h = s.grid.height, f = sizeof(float);
             py::dict d;
             for (size_t k = 0; k < s.panels.size(); ++k)
               d[py::str(s.panels[k].panel.layer)] = view(self, s.grid.at(int(k * size_t(w)), 0), {h, w, 3}, {3 * gw * f, 3 * f, f});
             return d;
           }, "Each panel by its layer name ('measured', 'cook_torrance_E2', ...): views of image, no copies.")
      .def_property_readonly("maps", [](const py::object& self) {
             const Sheet& s = self.cast<const PySheet&>().made.sheet;
             py::dict d;
             for (const PanelRender& p : s.panels) {
               if (!p.maps.available) continue;
               const py::ssize_t w = p.image.width, h = p.image.height, f = sizeof(float);
               py::dict maps;
               maps["reldiff"] = view(self, p.maps.relativeDifference.data(), {h, w}, {w * f, f});
               maps["flip"] = view(self, p.maps.flipMap.data(), {h, w}, {w * f, f});
               d[py::str(p.panel.layer)] = maps;
             }
             return d;
           }, "Each model's error maps against the measured panel: {'reldiff': (h, w), 'flip': (h, w)} (docs/sheets.md).")
      .def_property_readonly("figures", [](const PySheet& x) {
             py::dict d;
             for (const PanelRender& p : x.made.sheet.panels) d[py::str(p.panel.layer)] = panelFigures(x.made.sheet, p);
             return d;
           }, R"doc(
Per panel, by layer name: label, fit, colour, empty, note, spp, params, the fit's E1 and E2 against the
measured table, and against the measured panel the noise-free relative RMSE with its 95 % interval
(relative_rmse, relative_rmse_ci), the noisy one, the luminance ratio with its interval, HDR-ꟻLIP
with its interval (flip, flip_ci), and ΔE_ITP and SSIM of the panels as the PNG shows them with theirs
(delta_e_itp, delta_e_itp_ci, ssim, ssim_ci). A figure the sheet cannot give is None.
)doc")
      .def_property_readonly("verdict", [](const PySheet& x) { return verdictText(x.made.sheet); },
                             "The closest model when the intervals say so, a tie, or why there is no verdict.")
      .def_property_readonly("table", [](const PySheet& x) { return errorTable(x.made.sheet); },
                             "The error table `glossy sheet` prints.")
      .def_property_readonly("material", [](const PySheet& x) { return x.made.material.name; })
      .def_property_readonly("spp", [](const PySheet& x) { return x.made.sheet.spp; })
      .def_property_readonly("passes", [](const PySheet& x) { return x.made.sheet.passes; })
      .def_property_readonly("bsdf_samples", [](const PySheet& x) { return x.made.sheet.bsdfSamples; },
                             "BSDF samples at the object's vertices: 8 where the passes chose the spp and a panel is sharp, else 1.")
      .def_property_readonly("seconds", [](const PySheet& x) { return x.made.seconds; })
      .def_property_readonly("flip_noise_floor", [](const PySheet& x) {
             return optionalNumber(x.made.sheet.flipNoiseFloor >= 0.0, x.made.sheet.flipNoiseFloor);
           }, "ꟻLIP between the halves of the measured panel's samples: what noise alone scores.")
      .def_property_readonly("noise_floor", [](const PySheet& x) {
             const PanelRender& floor = x.made.sheet.noiseFloor;
             return floor.empty ? py::object(py::none()) : py::object(panelFigures(x.made.sheet, floor));
           }, "The noise-floor row: the measured panel against an independent render of itself (another seed, the same "
              "samples), with every figure of `figures`; None without a measured panel.")
      .def_property_readonly("warnings", [](const PySheet& x) { return x.made.sheet.warnings; },
                             "What makes the figures less than they seem (e.g. the intervals may be too narrow); while one "
                             "stands, the verdict names no model closest.")
      .def("save", [](const PySheet& x, const py::object& path) {
             guarded([&] {
               const std::string p = pathText(path);
               app::checkOutputFile(p, "path", {".exr"}, app::Folder::Create);
               app::writeSheetFiles(x.made, *x.stage, x.job, p);
             });
           }, py::arg("path"), "Writes the sheet's layered EXR and its PNG beside it, as `glossy sheet -o path` does.")
      .def("__repr__", [](const PySheet& x) {
        return "<glossy.Sheet " + x.made.material.name + ": " + std::to_string(x.made.sheet.spp) + " spp, " + verdictText(x.made.sheet) + ">";
      });

  m.def("sheet", [](const py::kwargs& a) { return guarded([&] { return renderSheetOf(a); }); }, R"doc(
sheet(*, material, measured=None, merl_dir=None, scene=None, camera=None, env=None, env_constant=None,
      env_rotate=0.0, spp=None, size=(256, 256), time=None, target_error=None, seed=0, threads=0,
      max_depth=8, light_samples=4, exposure=0.0, half=False, panels=None, progress=None,
      output=None) -> glossy.Sheet

Renders a material's comparison sheet as `glossy sheet` does: every panel from the same samples, each
model's error figures with 95 % intervals. spp (default 64) is split among 4 independent replicates;
time (seconds per panel) or target_error (the widest interval's half-width) render in passes until met;
target_error alone stops at 4096 spp (spp sets another cap), with a GlossyWarning when it stops short.
measured: the data for the measured panel (default: the one the material names, then the network
embedded beside it). panels: a grid's name ("lavoue2021", "ngan05") or "measured,MODEL:METRIC,..." as
`glossy sheet --panels` (default: the supplement's grid, glossy.comparison_grid()). progress(done, total) and Ctrl-C as in render(); total is 0 while unknown (time,
target_error). output: also write the EXR and PNG (or call Sheet.save later).
)doc");

  m.def("comparison_grid", [] {
          py::list rows;
          for (const auto& [p, inGrid] : gridTable()) {
            py::dict d;
            d["fit"] = p.fit.empty() ? std::string("measured") : p.fit;
            d["layer"] = p.layer, d["label"] = p.label, d["colour"] = p.colour, d["default"] = inGrid;
            rows.append(d);
          }
          return rows;
        }, R"doc(
The comparison grid's table, as sheets, plots and the report use it: a dict per panel with its fit
('measured' or MODEL:METRIC), EXR layer, label, colour ('#rrggbb') and whether the default grid shows it.
A fit of a model the table leaves out is still a panel (sheet(panels=...)), in grey.
)doc");

  m.def("read_exr", [](const py::object& path, const std::string& layer) {
          return guarded([&] {
            const std::string p = pathText(path);
            return imageArray(layer.empty() ? readRgbImage(p) : readImageLayer(p, layer));
          });
        }, py::arg("path"), py::arg("layer") = "", R"doc(
An EXR's RGB layer as float32 (height, width, 3): the default layer, or a sheet's panel layer by name
('measured', 'cook_torrance_E2', ...). Raises InputError naming the file for anything but a regular file
(a FIFO is refused, not waited on) and for an image that cannot be read.
)doc");
}

}  // namespace glossy::python
