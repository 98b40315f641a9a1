// The fits and view directions the sampler tests run on, the χ² grid that follows each model's lobe, and
// the check of one sampler: χ² plus weight = ρ cos θ_L / pdf and pdf(L) = sample.pdf for every sample.
#pragma once

#include "materials/models/brdf.h"
#include "materials/params/material_file.h"
#include "tests/support/chi2.h"

#include <array>
#include <ostream>
#include <string>
#include <vector>

namespace glossy::test {

struct LibraryFit {
  std::string name;  // "chrome ashikhmin-shirley:E1"
  Brdf brdf;
};

// Every fit of every parameter file in materials/.
std::vector<LibraryFit> libraryFits();
// The 42 fits of the six materials of the supplement text (shared/seed/supplement.txt): its 36 and glossy's
// GGX E2 fits.
std::vector<LibraryFit> supplementFits();
// The most extreme published fits, chosen by rule from the library: the 5 largest AS n; the 3 smallest and
// 3 largest CT m; for Microfacet and Smooth each the 3 largest B and the 2 smallest C; every fit with
// η ≥ 99.99; each rule takes fits no earlier rule took. Supplement fits are left out (tested anyway).
std::vector<LibraryFit> extremeFits();

// GGX beyond its library fits: a sharp lobe (α = 0.02) and a broad one (α = 0.5), over a Lambertian base.
std::vector<LibraryFit> ggxChi2Fits();

// The models of Ngan et al. 2005's published fits: each model's sharpest and broadest published fit (values from bbm's fits/*.fit, commit 9807fb38), over their own Lambertian bases.
std::vector<LibraryFit> publishedLobeChi2Fits();
// Bagher et al.'s SGD: its sharpest, a metal's and its broadest published fit; in the sweep only (libraryFits).
std::vector<LibraryFit> sgdChi2Fits();

// View elevations: head-on, two in between, and grazing (82°).
inline constexpr std::array<double, 4> kViewAnglesDeg = {0.0, 35.0, 65.0, 82.0};
inline constexpr std::array<double, 4> kViewAngles = {0.0, 35.0 * kPi / 180.0, 65.0 * kPi / 180.0,
                                                      82.0 * kPi / 180.0};
// V at elevation θ from N, at an azimuth off the frame's axes (0.6 rad).
Vec3 viewDirection(double theta);

struct SamplingCase {
  LibraryFit fit;
  double thetaV = 0.0;
  std::string label() const;     // "chrome ashikhmin-shirley:E1 at θv = 82°"
  std::string testName() const;  // "chrome_ashikhmin_shirley_E1_view82"
  unsigned seed() const;         // a stable hash of the name (FNV-1a), so each case draws its own stream
};
std::vector<SamplingCase> atViewAngles(const LibraryFit& fit);
void PrintTo(const SamplingCase& c, std::ostream* os);

// The χ² grid for a BRDF seen from V: cells packed around the mirror direction of V, at the angular width
// of the specular lobe's core (its quartile, from the model's parameters; 0.5 rad for diffuse models).
double lobeWidth(const Brdf& brdf);
LobeGrid gridFor(const Brdf& brdf, const Vec3& V);

struct SamplingCheck {
  Chi2Result chi2;
  long weightMismatches = 0;  // samples whose weight or pdf disagree with eval()/pdf()
};
// χ² of brdf's sampler seen from V on `grid`, checking weight = ρ cos θ_L / pdf and pdf(L) = sample.pdf
// for every sample on the way.
SamplingCheck checkSampler(const Brdf& brdf, const Vec3& V, const Chi2Grid& grid, long samples, unsigned seed,
                           double alpha);
// The same on gridFor(c.fit.brdf, V).
SamplingCheck checkSampler(const SamplingCase& c, long samples, unsigned seed, double alpha);

// The χ² family of the default suite: analytic samplers (the supplement's and the extreme fits, Lambertian,
// ggxChi2Fits and publishedLobeChi2Fits, at the four view angles) and measured ones (kMeasuredChi2Tests); one family-wise
// significance of 0.01 over all of them.
const std::vector<SamplingCase>& analyticChi2Family();
inline constexpr int kMeasuredChi2Tests = (3 + 6) * 4;  // 3 synthetic tables + shared/merl's 6, 4 views
inline constexpr double kChi2FamilyAlpha = 0.01;
double chi2TestAlpha();  // Šidák: per-test α for the whole family

}  // namespace glossy::test
