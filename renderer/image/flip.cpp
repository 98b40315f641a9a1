// HDR-ꟻLIP (flip.h), written from the papers: Andersson et al. 2020 (LDR-ꟻLIP, HPG) and 2021 (HDR-ꟻLIP,
// Eurographics short paper), one function per stage. Per exposure, both images are tone mapped and taken
// to YCxCz, where
//   colour:  the contrast sensitivity filters (a sum of Gaussians per opponent channel, at the viewing
//            condition's pixels per degree) blur them; the blurred images, back in linear RGB clamped to
//            [0,1], are compared in CIELAB with the Hunt adjustment (a, b scaled by 0.01 L) by HyAB
//            (|ΔL| + ‖Δ(a,b)‖), raised to 0.7 and mapped to [0,1] with 0.95 at 40 % of the largest
//            difference (green against blue);
//   feature: Gaussian first and second derivatives (σ = 0.082 / 2 degrees) of the lightness give edge and
//            point strengths; their largest difference, over √2, raised to 0.5, is ΔE_f;
// and the error is ΔE_c^(1 − ΔE_f). HDR-ꟻLIP keeps each pixel's largest error over the exposures.
//
// The 2D filters are applied separably (the blue-yellow one, a sum of two Gaussians, as two separable
// passes whose 1D kernels carry the square roots of its amplitudes), each kernel normalised to sum 1 over
// its square (the derivative kernels' positive and negative lobes to ±1 each), with image edges clamped:
// what flip-evaluator does, so that its means can be matched to 1e-3. Everything runs in float, as there.
// The code is deliberately plain: whole-image planes, one loop per stage, std::cbrt and std::pow. The one
// speed layer left is the filters' inner loop (weightedSum), written for vector registers, the only layer
// that clears the project's bar for speed layers on a sheet's time; docs/flip.md has the measurements, and
// docs/performance.md the layers that were tried and dropped.
#include "renderer/image/flip.h"

#include "materials/core/types.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace glossy {

namespace {

// The papers' constants: colour-difference exponent and the knee of its mapping to [0,1] (40 % of the
// largest difference maps to 0.95), the feature detectors' width in degrees and their exponent.
constexpr float kColourExponent = 0.7f, kKneeFraction = 0.4f, kKneeValue = 0.95f;
constexpr float kFeatureWidth = 0.082f, kFeatureExponent = 0.5f;
// ACES as fitted by Narkowicz, with the 0.6 pre-exposure the HDR-ꟻLIP paper cancels folded in:
// t(x) = (a x² + b x) / (c x² + d x + e); HDR-ꟻLIP's exposure range maps luminances to t = 0.85.
constexpr float kAcesA = 0.6f * 0.6f * 2.51f, kAcesB = 0.6f * 0.03f, kAcesC = 0.6f * 0.6f * 2.43f, kAcesD = 0.6f * 0.59f,
                kAcesE = 0.14f;
constexpr double kToneTarget = 0.85;

// Contrast sensitivity filters in the spatial domain (LDR-ꟻLIP, eq. 3): a sqrt(π/b) exp(−π² x²/b) summed
// over one or two terms per channel, x in degrees.
struct Csf {
  double a1, b1, a2, b2;
};
constexpr Csf kAchromatic{1.0, 0.0047, 0.0, 1e-5}, kRedGreen{1.0, 0.0053, 0.0, 1e-5}, kBlueYellow{34.1, 0.04, 13.5, 0.025};

// ---- Colour spaces ----

struct Float3 {  // colours in float, as flip-evaluator computes them
  float x, y, z;
};

struct Mat3 {
  double m[3][3] = {};
  Mat3 operator*(const Mat3& o) const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) r.m[i][j] += m[i][k] * o.m[k][j];
    return r;
  }
  Mat3 inverse() const {  // by cofactors
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        r.m[i][j] = (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]) / det;
      }
    return r;
  }
};

// An affine map in float, as the per-pixel conversions use it.
struct Affine {
  float m[3][3] = {}, offset[3] = {};
  Affine() = default;
  Affine(const Mat3& linear, const double (&shift)[3]) {
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) m[i][j] = float(linear.m[i][j]);
      offset[i] = float(shift[i]);
    }
  }
  Float3 operator()(const Float3& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z + offset[0], m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z + offset[1],
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z + offset[2]};
  }
};

// From the sRGB primaries and D65: linear RGB → XYZ over the white (CIELAB's argument); linear RGB ↔ YCxCz
// (Edge and Wandell's linearised CIELAB, in which the filters act).
struct ColourSpaces {
  Affine rgbToXyzOverWhite, rgbToYcxcz, ycxczToRgb;
  float maxDifference = 0;  // HyAB^0.7 of green against blue, the largest in the gamut
};

float clamp01(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }  // NaN → 0

// Hunt-adjusted CIELAB (L, 0.01 L a, 0.01 L b) of a linear RGB colour in [0,1].
Float3 huntLab(const Float3& rgb, const Affine& rgbToXyzOverWhite) {
  const Float3 t = rgbToXyzOverWhite(rgb);
  auto f = [](float v) {
    constexpr float delta = 6.0f / 29.0f;
    return v > delta * delta * delta ? std::cbrt(v) : v / (3.0f * delta * delta) + 4.0f / 29.0f;
  };
  const float fx = f(t.x), fy = f(t.y), fz = f(t.z);
  const float l = 116.0f * fy - 16.0f;
  return {l, 0.01f * l * (500.0f * (fx - fy)), 0.01f * l * (200.0f * (fy - fz))};
}

float hyab(const Float3& p, const Float3& q) {
  const float da = p.y - q.y, db = p.z - q.z;
  return std::fabs(p.x - q.x) + std::sqrt(da * da + db * db);
}

const ColourSpaces& colourSpaces() {
  static const ColourSpaces spaces = [] {
    // Columns: the primaries' XYZ, scaled so that RGB (1,1,1) is D65 with Y = 1.
    const double xy[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};
    const double white[3] = {0.3127 / 0.3290, 1.0, (1.0 - 0.3127 - 0.3290) / 0.3290};
    Mat3 rgbToXyz;
    for (int j = 0; j < 3; ++j) {
      rgbToXyz.m[0][j] = xy[j][0] / xy[j][1];
      rgbToXyz.m[1][j] = 1.0;
      rgbToXyz.m[2][j] = (1.0 - xy[j][0] - xy[j][1]) / xy[j][1];
    }
    const Mat3 inverse = rgbToXyz.inverse();
    for (int j = 0; j < 3; ++j) {
      const double s = inverse.m[j][0] * white[0] + inverse.m[j][1] * white[1] + inverse.m[j][2] * white[2];
      for (int i = 0; i < 3; ++i) rgbToXyz.m[i][j] *= s;
    }
    Mat3 overWhite;
    for (int i = 0; i < 3; ++i) overWhite.m[i][i] = 1.0 / white[i];
    // YCxCz = (116 Y/Yw − 16, 500 (X/Xw − Y/Yw), 200 (Y/Yw − Z/Zw)).
    const Mat3 ycxczOfXyzOverWhite{{{0.0, 116.0, 0.0}, {500.0, -500.0, 0.0}, {0.0, 200.0, -200.0}}};
    const Mat3 rgbToYcxcz = ycxczOfXyzOverWhite * overWhite * rgbToXyz, ycxczToRgb = rgbToYcxcz.inverse();
    ColourSpaces s;
    s.rgbToXyzOverWhite = Affine(overWhite * rgbToXyz, {0.0, 0.0, 0.0});
    s.rgbToYcxcz = Affine(rgbToYcxcz, {-16.0, 0.0, 0.0});
    s.ycxczToRgb = Affine(ycxczToRgb, {16.0 * ycxczToRgb.m[0][0], 16.0 * ycxczToRgb.m[1][0], 16.0 * ycxczToRgb.m[2][0]});
    s.maxDifference = std::pow(hyab(huntLab({0, 1, 0}, s.rgbToXyzOverWhite), huntLab({0, 0, 1}, s.rgbToXyzOverWhite)),
                               kColourExponent);
    return s;
  }();
  return spaces;
}

// ---- Images and filters ----

// One channel of an image, row-major.
struct Plane {
  int w = 0, h = 0;
  std::vector<float> v;
  Plane(int width, int height) : w(width), h(height), v(size_t(width) * size_t(height), 0.0f) {}
  float* row(int y) { return v.data() + size_t(y) * size_t(w); }
  const float* row(int y) const { return v.data() + size_t(y) * size_t(w); }
};

// A 1D kernel of 2 r + 1 weights, centred.
using Kernel = std::vector<float>;
int radius(const Kernel& k) { return int(k.size() / 2); }

// out[x] = Σ_i k[i] sources[i][x] for x < w: a correlation whose i-th tap reads sources[i]. Sixteen
// outputs at a time, as two vectors of 8 lanes (GCC's vector extension) whose sums stay in registers while
// the taps go by, and compiled twice, for x86-64-v3 (AVX2, FMA) and the baseline, chosen at load time.
using Lanes = float __attribute__((vector_size(8 * sizeof(float))));
#pragma GCC diagnostic ignored "-Wpsabi"  // no Lanes crosses a call, so the vector ABI warning concerns nothing
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target_clones("arch=x86-64-v3", "default")))
#endif
void weightedSum(const Kernel& k, const std::vector<const float*>& sources, int w, float* out) {
  int x = 0;
  for (; x + 16 <= w; x += 16) {
    Lanes low{}, high{};
    for (size_t i = 0; i < k.size(); ++i) {
      Lanes a, b;
      std::memcpy(&a, sources[i] + x, sizeof a);
      std::memcpy(&b, sources[i] + x + 8, sizeof b);
      low += k[i] * a, high += k[i] * b;
    }
    std::memcpy(out + x, &low, sizeof low);
    std::memcpy(out + x + 8, &high, sizeof high);
  }
  for (; x < w; ++x) {
    float sum = 0.0f;
    for (size_t i = 0; i < k.size(); ++i) sum += k[i] * sources[i][x];
    out[x] = sum;
  }
}

// Each row correlated with k, pixels beyond the ends taken as the end pixels.
Plane filterRows(const Plane& in, const Kernel& k) {
  const int r = radius(k);
  Plane out(in.w, in.h);
  std::vector<float> padded(size_t(in.w + 2 * r));
  std::vector<const float*> sources(k.size());
  for (int i = 0; i <= 2 * r; ++i) sources[size_t(i)] = padded.data() + i;
  for (int y = 0; y < in.h; ++y) {
    for (int x = -r; x < in.w + r; ++x) padded[size_t(x + r)] = in.row(y)[std::clamp(x, 0, in.w - 1)];
    weightedSum(k, sources, in.w, out.row(y));
  }
  return out;
}

// Each column correlated with k, rows beyond the edges taken as the edge rows.
Plane filterColumns(const Plane& in, const Kernel& k) {
  const int r = radius(k);
  Plane out(in.w, in.h);
  std::vector<const float*> sources(k.size());
  for (int y = 0; y < in.h; ++y) {
    for (int i = -r; i <= r; ++i) sources[size_t(i + r)] = in.row(std::clamp(y + i, 0, in.h - 1));
    weightedSum(k, sources, in.w, out.row(y));
  }
  return out;
}

Plane filter2d(const Plane& in, const Kernel& horizontal, const Kernel& vertical) {
  return filterColumns(filterRows(in, horizontal), vertical);
}

struct Kernels {
  Kernel achromatic, redGreen, blueYellow1, blueYellow2;  // contrast sensitivity
  Kernel gauss, firstDerivative, secondDerivative;        // feature detection
};

Kernels makeKernels(double ppd) {
  Kernels k;
  // The CSF kernels reach three standard deviations of the widest Gaussian: exp(−π² x²/b) has
  // σ² = b / (2π²) degrees².
  const double widest = std::max({kAchromatic.b1, kRedGreen.b1, kBlueYellow.b1, kBlueYellow.b2});
  const int r = int(std::ceil(3.0 * std::sqrt(widest / (2.0 * kPi * kPi)) * ppd));
  auto term = [](double x, double a, double b) { return a * std::sqrt(kPi / b) * std::exp(-kPi * kPi * x * x / b); };
  std::vector<double> y, rg, by1, by2;
  for (int i = -r; i <= r; ++i) {
    const double x = i / ppd;
    y.push_back(term(x, kAchromatic.a1, kAchromatic.b1));
    rg.push_back(term(x, kRedGreen.a1, kRedGreen.b1));
    // Two 1D kernels sqrt(a sqrt(π/b)) exp(−π² x²/b) multiply to the 2D term a sqrt(π/b) exp(−π² r²/b).
    by1.push_back(std::sqrt(term(0.0, kBlueYellow.a1, kBlueYellow.b1)) * std::exp(-kPi * kPi * x * x / kBlueYellow.b1));
    by2.push_back(std::sqrt(term(0.0, kBlueYellow.a2, kBlueYellow.b2)) * std::exp(-kPi * kPi * x * x / kBlueYellow.b2));
  }
  auto sum = [](const std::vector<double>& v) {
    double s = 0;
    for (double e : v) s += e;
    return s;
  };
  auto scaled = [](const std::vector<double>& v, double s) {
    Kernel out;
    for (double e : v) out.push_back(float(e * s));
    return out;
  };
  k.achromatic = scaled(y, 1.0 / sum(y));
  k.redGreen = scaled(rg, 1.0 / sum(rg));
  // The 2D blue-yellow kernel sums to sum(by1)² + sum(by2)²; this scale of both 1D pairs makes it 1.
  const double byNorm = 1.0 / std::hypot(sum(by1), sum(by2));
  k.blueYellow1 = scaled(by1, byNorm);
  k.blueYellow2 = scaled(by2, byNorm);

  const double sigma = 0.5 * kFeatureWidth * ppd;  // pixels
  const int rf = int(std::ceil(3.0 * sigma));
  std::vector<double> g, dg, ddg;
  for (int i = -rf; i <= rf; ++i) {
    const double x = i, gauss = std::exp(-x * x / (2.0 * sigma * sigma));
    g.push_back(gauss);
    dg.push_back(-x * gauss);
    ddg.push_back((x * x / (sigma * sigma) - 1.0) * gauss);
  }
  // The Gaussian sums to 1; each derivative's positive and negative weights to +1 and −1 (where there are
  // any: at a fraction of a pixel per degree the off-centre taps underflow to 0).
  auto lobesToUnit = [](const std::vector<double>& v) {
    double positive = 0, negative = 0;
    for (double e : v) (e > 0 ? positive : negative) += std::fabs(e);
    Kernel out;
    for (double e : v) out.push_back(float(e > 0 ? e / positive : e < 0 ? e / negative : 0.0));
    return out;
  };
  k.gauss = scaled(g, 1.0 / sum(g));
  k.firstDerivative = lobesToUnit(dg);
  k.secondDerivative = lobesToUnit(ddg);
  return k;
}

// ---- The stages of LDR-ꟻLIP ----

// An image as the stages see it: YCxCz, and the lightness L/100 in [0,1] that the feature detectors use.
struct Opponent {
  Plane y, cx, cz, lightness;
};

// Stage 1: exposed by `multiplier`, tone mapped by ACES and clamped to [0,1] (a NaN from ∞/∞, at an
// infinite or overflowing input, becomes 0), then YCxCz.
Opponent toneMappedYcxcz(const RgbImage& image, float multiplier) {
  const int w = image.width, h = image.height;
  Opponent o{Plane(w, h), Plane(w, h), Plane(w, h), Plane(w, h)};
  auto toneMap = [](float x) { return clamp01((x * x * kAcesA + x * kAcesB) / (x * x * kAcesC + x * kAcesD + kAcesE)); };
  const Affine& toYcxcz = colourSpaces().rgbToYcxcz;
  for (size_t i = 0; i < o.y.v.size(); ++i) {
    const float* p = &image.pixels[3 * i];
    const Float3 c = toYcxcz({toneMap(p[0] * multiplier), toneMap(p[1] * multiplier), toneMap(p[2] * multiplier)});
    o.y.v[i] = c.x, o.cx.v[i] = c.y, o.cz.v[i] = c.z;
    o.lightness.v[i] = (c.x + 16.0f) / 116.0f;
  }
  return o;
}

// Stage 2: the contrast sensitivity filters, channel by channel (blue-yellow as the sum of its two terms).
Opponent csfFiltered(const Opponent& in, const Kernels& k) {
  Plane cz = filter2d(in.cz, k.blueYellow1, k.blueYellow1);
  const Plane cz2 = filter2d(in.cz, k.blueYellow2, k.blueYellow2);
  for (size_t i = 0; i < cz.v.size(); ++i) cz.v[i] += cz2.v[i];
  return {filter2d(in.y, k.achromatic, k.achromatic), filter2d(in.cx, k.redGreen, k.redGreen), std::move(cz), Plane(0, 0)};
}

// Stage 3: ΔE_c, the Hunt-adjusted HyAB distance of the filtered images (back in linear RGB clamped to
// [0,1]), raised to 0.7 and mapped to [0, 0.95] below the knee at 40 % of the largest, (0.95, 1] above.
Plane colourDifference(const Opponent& a, const Opponent& b) {
  const ColourSpaces& cs = colourSpaces();
  auto lab = [&](const Opponent& o, size_t i) {
    const Float3 rgb = cs.ycxczToRgb({o.y.v[i], o.cx.v[i], o.cz.v[i]});
    return huntLab({clamp01(rgb.x), clamp01(rgb.y), clamp01(rgb.z)}, cs.rgbToXyzOverWhite);
  };
  const float cmax = cs.maxDifference, knee = kKneeFraction * cmax;
  Plane out(a.y.w, a.y.h);
  for (size_t i = 0; i < out.v.size(); ++i) {
    const float e = std::pow(hyab(lab(a, i), lab(b, i)), kColourExponent);
    out.v[i] = e < knee ? e * (kKneeValue / knee) : kKneeValue + (e - knee) / (cmax - knee) * (1.0f - kKneeValue);
  }
  return out;
}

// Edge and point strengths of a lightness plane: the lengths of its Gaussian first- and second-derivative
// gradients.
struct Features {
  Plane edge, point;
};
Features features(const Plane& lightness, const Kernels& k) {
  const Plane dx = filter2d(lightness, k.firstDerivative, k.gauss), dy = filter2d(lightness, k.gauss, k.firstDerivative);
  const Plane ddx = filter2d(lightness, k.secondDerivative, k.gauss), ddy = filter2d(lightness, k.gauss, k.secondDerivative);
  Features f{Plane(lightness.w, lightness.h), Plane(lightness.w, lightness.h)};
  for (size_t i = 0; i < lightness.v.size(); ++i) {
    f.edge.v[i] = std::sqrt(dx.v[i] * dx.v[i] + dy.v[i] * dy.v[i]);
    f.point.v[i] = std::sqrt(ddx.v[i] * ddx.v[i] + ddy.v[i] * ddy.v[i]);
  }
  return f;
}

// Stage 4: ΔE_f = (max(|Δ edge|, |Δ point|) / √2)^0.5.
Plane featureDifference(const Plane& lightnessA, const Plane& lightnessB, const Kernels& k) {
  const Features a = features(lightnessA, k), b = features(lightnessB, k);
  Plane out(lightnessA.w, lightnessA.h);
  for (size_t i = 0; i < out.v.size(); ++i) {
    const float difference = std::max(std::fabs(a.edge.v[i] - b.edge.v[i]), std::fabs(a.point.v[i] - b.point.v[i]));
    out.v[i] = std::pow(difference / std::sqrt(2.0f), kFeatureExponent);
  }
  return out;
}

// Stages 1-5 at one exposure: LDR-ꟻLIP, ΔE_c^(1 − ΔE_f), clamped to [0,1].
Plane ldrFlip(const RgbImage& reference, const RgbImage& test, float multiplier, const Kernels& k) {
  const Opponent a = toneMappedYcxcz(reference, multiplier), b = toneMappedYcxcz(test, multiplier);
  const Plane colour = colourDifference(csfFiltered(a, k), csfFiltered(b, k));
  const Plane feature = featureDifference(a.lightness, b.lightness, k);
  Plane out(colour.w, colour.h);
  for (size_t i = 0; i < out.v.size(); ++i) out.v[i] = clamp01(std::pow(colour.v[i], 1.0f - feature.v[i]));
  return out;
}

void checkImage(const RgbImage& image, const char* which) {
  if (image.width <= 0 || image.height <= 0)
    throw std::invalid_argument(std::string("hdrFlip: the ") + which + " image is empty");
  if (image.pixels.size() != size_t(image.width) * size_t(image.height) * 3)
    throw std::invalid_argument(std::string("hdrFlip: the ") + which + " image's pixel buffer is not width × height × 3");
}

}  // namespace

FlipExposures hdrFlipExposures(const RgbImage& reference) {
  checkImage(reference, "reference");
  // x_max: the larger root of t(x) = 0.85, (a − 0.85 c) x² + (b − 0.85 d) x − 0.85 e = 0.
  const double qa = kAcesA - kToneTarget * kAcesC, qb = kAcesB - kToneTarget * kAcesD, qc = -kToneTarget * kAcesE;
  const double xMax = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
  std::vector<float> luminance;
  luminance.reserve(reference.pixels.size() / 3);
  for (size_t i = 0; i < reference.pixels.size(); i += 3) {
    const float* p = &reference.pixels[i];
    const float y = 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
    if (std::isfinite(y)) luminance.push_back(y);
  }
  float yMax = 0.0f, yMedian = 0.0f;
  if (!luminance.empty()) {
    yMax = *std::max_element(luminance.begin(), luminance.end());
    auto mid = luminance.begin() + ptrdiff_t(luminance.size() / 2);
    std::nth_element(luminance.begin(), mid, luminance.end());
    yMedian = *mid;
  }
  FlipExposures e;
  e.stop = float(std::log2(xMax / std::max(yMedian, FLT_EPSILON)));
  e.start = std::min(float(std::log2(xMax / std::max(yMax, FLT_EPSILON))), e.stop);
  e.count = int(std::max(2.0f, std::ceil(e.stop - e.start)));
  return e;
}

FlipMap hdrFlip(const RgbImage& reference, const RgbImage& test, const FlipSettings& settings) {
  checkImage(reference, "reference");
  checkImage(test, "test");
  if (reference.width != test.width || reference.height != test.height)
    throw std::invalid_argument("hdrFlip: the reference is " + std::to_string(reference.width) + "x" +
                                std::to_string(reference.height) + ", the test " + std::to_string(test.width) + "x" +
                                std::to_string(test.height));
  const double ppd = settings.pixelsPerDegree;
  if (!(ppd > 0.0 && ppd <= 1000.0))
    throw std::invalid_argument("hdrFlip: pixels per degree must be in (0, 1000], not " + std::to_string(ppd));

  const FlipExposures exposures = hdrFlipExposures(reference);
  const Kernels kernels = makeKernels(ppd);
  const float step = (exposures.stop - exposures.start) / float(exposures.count - 1);
  const size_t n = size_t(reference.width) * size_t(reference.height);

  // Stage 6: each pixel's largest error over the exposures (a running maximum per thread, then over threads).
  tbb::combinable<std::vector<float>> largest([n] { return std::vector<float>(n, 0.0f); });
  tbb::parallel_for(0, exposures.count, [&](int i) {
    const Plane map = ldrFlip(reference, test, std::exp2(exposures.start + float(i) * step), kernels);
    std::vector<float>& mine = largest.local();
    for (size_t j = 0; j < n; ++j) mine[j] = std::max(mine[j], map.v[j]);
  });
  FlipMap result;
  result.width = reference.width;
  result.height = reference.height;
  result.error.assign(n, 0.0f);
  largest.combine_each([&](const std::vector<float>& mine) {
    for (size_t j = 0; j < n; ++j) result.error[j] = std::max(result.error[j], mine[j]);
  });
  double sum = 0.0;
  for (float v : result.error) sum += v;
  result.mean = sum / double(n);
  return result;
}

}  // namespace glossy
