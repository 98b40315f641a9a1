// glossy.delta_e_itp and glossy.ssim: the sheets' display figures (renderer/image/delta_e_itp.h, ssim.h) as
// per-pixel maps of any two images, so that a user can score renders glossy did not make, or the same
// panels at another exposure, by the sheets' own definitions.
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/image/delta_e_itp.h"
#include "renderer/image/ssim.h"
#include "renderer/python/module_support.h"

#include <vector>

namespace glossy::python {

namespace {

using InImage = py::array_t<float, py::array::c_style | py::array::forcecast>;

RgbImage imageOf(const py::handle& value, const char* name) {
  const InImage a = InImage::ensure(value);
  if (!a) {
    PyErr_Clear();
    throw InputError(formatted("%s: not an array of numbers", name));
  }
  if (a.ndim() != 3 || a.shape(2) != 3 || a.shape(0) < 1 || a.shape(1) < 1 || a.shape(0) > 65536 || a.shape(1) > 65536)
    throw InputError(formatted("%s: expected shape (height, width, 3), each side 1 to 65536", name));
  RgbImage image(int(a.shape(1)), int(a.shape(0)));
  std::copy(a.data(), a.data() + image.pixels.size(), image.pixels.begin());
  return image;
}

// Both images read and checked, of one size.
std::pair<RgbImage, RgbImage> pairOf(const py::handle& reference, const py::handle& test) {
  std::pair<RgbImage, RgbImage> p{imageOf(reference, "reference"), imageOf(test, "test")};
  if (p.first.width != p.second.width || p.first.height != p.second.height)
    throw InputError(formatted("reference and test: %dx%d and %dx%d (give two images of one size)", p.first.width, p.first.height,
                               p.second.width, p.second.height));
  return p;
}

}  // namespace

void bindImages(py::module_& m) {
  m.def("delta_e_itp", [](const py::handle& reference, const py::handle& test, double white, double black) {
          return guarded([&] {
            if (!(white > 0.0 && white <= 10000.0 && black >= 0.0 && black < white))
              throw InputError(formatted("white and black: need 0 <= black < white <= 10000 cd/m2, not %g and %g", white, black));
            const auto [r, t] = pairOf(reference, test);
            return floatArray(deltaEItpMap(r, t, SdrDisplay{white, black}), {r.height, r.width});
          });
        }, py::arg("reference"), py::arg("test"), py::arg("white") = SdrDisplay{}.white, py::arg("black") = SdrDisplay{}.black, R"doc(
The per-pixel ΔE_ITP (ITU-R BT.2124) of two linear Rec. 709 images (height, width, 3) as an SDR display of
white and black luminance (cd/m²) shows them: each channel clipped to [0, 1], NaN black. A sheet's figure is
its mean over the object's pixels at exposure 0 (docs/sheets.md); scale the images by 2**exposure first to
score them at another. Returns float32 (height, width).
)doc");
  m.def("ssim", [](const py::handle& reference, const py::handle& test) {
          return guarded([&] {
            const auto [r, t] = pairOf(reference, test);
            return floatArray(ssimMap(r, t), {r.height, r.width});
          });
        }, py::arg("reference"), py::arg("test"), R"doc(
The per-pixel SSIM (Wang et al. 2004; 11×11 Gaussian window, σ 1.5, the three channels' mean) of two
linear Rec. 709 images (height, width, 3), sRGB-encoded and clipped as a sheet's PNG shows them. A sheet's
figure is its mean over the object's pixels at exposure 0 (docs/sheets.md). Returns float32 (height, width).
)doc");
}

}  // namespace glossy::python
