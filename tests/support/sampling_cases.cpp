#include "tests/support/sampling_cases.h"

#include "tests/support/test_support.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

namespace glossy::test {

namespace {

struct FitRecord {
  std::string material;
  Fit fit;
};

std::vector<FitRecord> libraryRecords() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(materialsDir()))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<FitRecord> all;
  for (const auto& path : files) {
    const MaterialFile m = loadMaterialFile(path);
    for (const Fit& f : m.fits) all.push_back({m.name, f});
  }
  return all;
}

LibraryFit toLibraryFit(const FitRecord& r) { return {r.material + " " + r.fit.id.str(), makeBrdf(r.fit)}; }

bool isSupplement(const std::string& material) {
  const std::vector<std::string>& names = supplementMaterials();
  return std::find(names.begin(), names.end(), material) != names.end();
}

// x in [0, xMax] below which a fraction q of the profile (1 + B x)^(−C) lies (closed form of its integral).
double abcQuantile(double b, double c, double xMax, double q) {
  if (b * xMax < 1e-9) return q * xMax;
  if (std::abs(1.0 - c) < 1e-9) return std::expm1(q * std::log1p(b * xMax)) / b;
  const double k = 1.0 - c;
  return std::expm1(std::log1p(q * std::expm1(k * std::log1p(b * xMax))) / k) / b;
}

}  // namespace

std::vector<LibraryFit> libraryFits() {
  // Bagher et al.'s SGD fits are left to sgdChi2Fits: the χ² grid's adaptive integration refines along every
  // bin edge of their tabulated, piecewise-constant density, so each case is far slower than a closed-form lobe's.
  std::vector<LibraryFit> all;
  for (const FitRecord& r : libraryRecords())
    if (r.fit.id.model != "sgd") all.push_back(toLibraryFit(r));
  return all;
}

std::vector<LibraryFit> supplementFits() {
  const std::vector<FitRecord> records = libraryRecords();
  // A refit of glossy's beside its published fit (same model and metric, a lobe of nearly the same shape)
  // adds no case to the samplers' test; glossy's fit of a model with no published one (GGX) does.
  const auto refit = [&](const FitRecord& r) {
    return r.fit.id.isGlossys() && std::any_of(records.begin(), records.end(), [&](const FitRecord& p) {
             return p.material == r.material && p.fit.id == FitId{r.fit.id.model, r.fit.id.metric};
           });
  };
  // Ngan et al.'s and Bagher et al.'s fits of the six are left to publishedLobeChi2Fits (each model's extremes)
  // and the sweep.
  std::vector<LibraryFit> out;
  for (const FitRecord& r : records)
    if (isSupplement(r.material) && !refit(r) && r.fit.id.isLowMetric()) out.push_back(toLibraryFit(r));
  return out;
}

std::vector<LibraryFit> extremeFits() {
  std::vector<FitRecord> candidates;
  for (FitRecord& r : libraryRecords())
    if (!isSupplement(r.material)) candidates.push_back(std::move(r));

  std::vector<FitRecord> chosen;
  std::set<std::string> seen;
  const auto take = [&](const std::string& model, const char* key, bool largest, size_t count) {
    std::vector<const FitRecord*> ofModel;
    for (const FitRecord& r : candidates)
      if (r.fit.id.model == model) ofModel.push_back(&r);
    std::sort(ofModel.begin(), ofModel.end(), [&](const FitRecord* a, const FitRecord* b) {
      const double x = a->fit.params.scalar(key), y = b->fit.params.scalar(key);
      return largest ? x > y : x < y;
    });
    size_t taken = 0;
    for (size_t k = 0; k < ofModel.size() && taken < count; ++k)
      if (seen.insert(ofModel[k]->material + ofModel[k]->fit.id.str()).second) {
        chosen.push_back(*ofModel[k]);
        ++taken;
      }
  };
  take("ashikhmin-shirley", "n", true, 5);
  take("cook-torrance", "m", false, 3);
  take("cook-torrance", "m", true, 3);
  take("microfacet", "b", true, 3);
  take("microfacet", "c", false, 2);
  take("smooth", "b", true, 3);
  take("smooth", "c", false, 2);
  for (const FitRecord& r : candidates)
    if (r.fit.params.has("eta") && r.fit.params.scalar("eta") >= 99.99 && seen.insert(r.material + r.fit.id.str()).second)
      chosen.push_back(r);

  std::vector<LibraryFit> out;
  for (const FitRecord& r : chosen) out.push_back(toLibraryFit(r));
  return out;
}

std::vector<LibraryFit> ggxChi2Fits() {
  return {{"ggx alpha=0.02", Ggx{Rgb(0.1), Rgb(1.0), 0.02, 1.5}}, {"ggx alpha=0.5", Ggx{Rgb(0.1), Rgb(1.0), 0.5, 1.5}}};
}

namespace {

// Bagher et al.'s fits, every parameter per channel: kd, ks, alpha, p, f0, f1, norm, lambda, c, k, theta0.
Brdf sgdFit(std::initializer_list<Rgb> values) {
  static constexpr const char* keys[] = {"kd", "ks", "alpha", "p", "f0", "f1", "norm", "lambda", "c", "k", "theta0"};
  ParamSet params;
  const Rgb* v = values.begin();
  for (const char* key : keys) params.set(key, *v++);
  return Sgd::fromParams(params);
}

}  // namespace

std::vector<LibraryFit> sgdChi2Fits() {
  return {
      // SGD: specular-orange-phenolic (α down to 1.6e-5, the sharpest; channels of different widths),
      // chrome-steel (a metal whose shadowing has c up to 1.6e109) and teflon (α 0.58-0.68, p up to 1.44).
      {"sgd specular-orange-phenolic",
       sgdFit({Rgb(0.32771, 0.0540131, 0.00883213), Rgb(0.051915, 0.0686764, 0.0489478), Rgb(7.91913e-05, 0.000139576, 1.62017e-05),
               Rgb(0.253564, 0.354675, 3.55583e-12), Rgb(0.0768695, 0.0496641, 0.0223538), Rgb(-0.015514, -0.023864, -0.0433847),
               Rgb(10274.5, 5159.16, 61722.9), Rgb(7.4207, 3.83488, 8722070.0), Rgb(2.91305e+71, 1.02522e-07, 23012400.0),
               Rgb(170.364, 373.255, 855.811), Rgb(1.19475, 0.53082, 0.608547)})},
      {"sgd chrome-steel",
       sgdFit({Rgb(0.0206718, 0.0240818, 0.024351), Rgb(0.129782, 0.109032, 0.0524555), Rgb(5.51292e-05, 3.13288e-05, 4.51944e-05),
               Rgb(0.207979, 0.152758, 0.325431), Rgb(1.18818e-12, 2.06813e-11, 0.580895), Rgb(-0.316807, -0.265326, -0.419105),
               Rgb(15466.8, 28628.9, 16531.2), Rgb(12.8988, 68.7898, 4.68237), Rgb(1.43049e+84, 1.63655e+109, 44.7025),
               Rgb(197.744, 257.536, 618.155), Rgb(1.20035, 1.2003, 0.579562)})},
      {"sgd teflon",
       sgdFit({Rgb(0.276442, 0.263098, 0.260294), Rgb(1.56924, 1.52804, 1.43859), Rgb(0.678586, 0.662167, 0.577852),
               Rgb(1.2402, 1.14126, 1.44077), Rgb(9.40662e-13, 3.57656e-11, 1.50208e-11), Rgb(-0.0492032, -0.0587316, -0.0548028),
               Rgb(3.91532, 3.82834, 3.64944), Rgb(2.09871, 2.05044, 2.90315), Rgb(0.0378525, 0.0435869, 0.0028469),
               Rgb(6.8689, 6.72229, 9.65585), Rgb(0.166634, 0.181605, -0.0468321)})},
  };
}

std::vector<LibraryFit> publishedLobeChi2Fits() {
  return {
      // Ward: hematite (α = 0.00576, the sharpest) and red-fabric (α = 0.5, the broadest, Ngan's bound).
      {"ward hematite", Ward{Rgb(0.0317, 0.0275, 0.0191), Rgb(0.0849, 0.0739, 0.0513), 0.00576}},
      {"ward red-fabric", Ward{Rgb(0.176, 0.017, 0.00287), Rgb(0.063, 0.0134, 0.00565), 0.5}},
      {"ward-duer hematite", WardDuer{Rgb(0.0366, 0.0318, 0.0221), Rgb(0.0601, 0.0523, 0.0363), 0.00509}},
      {"ward-duer pink-plastic", WardDuer{Rgb(0.367, 0.0715, 0.0344), Rgb(0.0366, 0.0241, 0.0173), 0.5}},
      // Blinn-Phong: specular-violet-phenolic (n = 1.21e5) and yellow-paint (n = 9.02; the broader
      // polyurethane-foam fit has no lobe, Ks = 0).
      {"blinn-phong specular-violet-phenolic", BlinnPhong{Rgb(0.0708, 0.0167, 0.013), Rgb(0.00109, 0.000602, 0.000442), 121000.0}},
      {"blinn-phong yellow-paint", BlinnPhong{Rgb(0.29, 0.161, 0.0139), Rgb(0.014, 0.0115, 0.00616), 9.02}},
      // Lafortune: hematite (n = 1.66e4) and beige-fabric (n = 2.29, Cz = 5e-8: a lobe about a nearly horizontal axis).
      {"lafortune hematite", Lafortune{Rgb(0.03, 0.0261, 0.0181), Rgb(0.0802, 0.0698, 0.0484), -0.577, 0.577, 16600.0}},
      {"lafortune beige-fabric", Lafortune{Rgb(0.241, 0.141, 0.0842), Rgb(0.1, 0.0653, 0.0371), -0.707, 5.09e-08, 2.29}},
      {"ngan-ashikhmin-shirley hematite", NganAshikhminShirley{Rgb(0.0368, 0.032, 0.0222), Rgb(0.0599, 0.0521, 0.0362), 0.999, 78200.0}},
      {"ngan-ashikhmin-shirley beige-fabric", NganAshikhminShirley{Rgb(0.199, 0.112, 0.0664), Rgb(0.197, 0.136, 0.0822), 0.973, 0.5}},
      {"ngan-cook-torrance hematite", NganCookTorrance{Rgb(0.0364, 0.0316, 0.022), Rgb(0.102, 0.0889, 0.0617), 0.599, 0.00512}},
      {"ngan-cook-torrance polyurethane-foam", NganCookTorrance{Rgb(0.0663, 0.0205, 0.00926), Rgb(0.144, 0.0792, 0.0491), 0.206, 0.943}},
  };
}

Vec3 viewDirection(double theta) {
  const double phi = 0.6;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

std::string SamplingCase::label() const {
  return fit.name + " at θv = " + std::to_string(int(std::lround(thetaV * 180.0 / kPi))) + "°";
}

std::string SamplingCase::testName() const {
  std::string s = fit.name + "_view" + std::to_string(int(std::lround(thetaV * 180.0 / kPi)));
  for (char& ch : s)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return s;
}

unsigned SamplingCase::seed() const {
  uint32_t h = 2166136261u;
  for (unsigned char ch : testName()) h = (h ^ ch) * 16777619u;
  return h;
}

std::vector<SamplingCase> atViewAngles(const LibraryFit& fit) {
  std::vector<SamplingCase> out;
  for (double theta : kViewAngles) out.push_back({fit, theta});
  return out;
}

void PrintTo(const SamplingCase& c, std::ostream* os) { *os << c.label(); }

double lobeWidth(const Brdf& brdf) {
  constexpr double q = 0.25;
  double width = 0.5;  // Lambertian, measured data
  // Half-vector lobes: the angle of L from the mirror direction is about twice θ_h.
  if (const auto* m = brdf.as<AshikhminShirley>()) {
    width = 2.0 * std::acos(std::pow(1.0 - q, 1.0 / (m->n + 1.0)));  // cos θ_h = ξ^(1/(n+1))
  } else if (const auto* m = brdf.as<CookTorrance>()) {
    width = 2.0 * std::atan(m->m * std::sqrt(-std::log(1.0 - q)));  // tan² θ_h = −m² ln(1 − ξ)
  } else if (const auto* m = brdf.as<Microfacet>()) {
    const double x = abcQuantile(m->b, m->c, 1.0, q);  // x = 1 − cos θ_h
    width = 2.0 * std::sqrt(x * (2.0 - x));
  } else if (const auto* m = brdf.as<Smooth>()) {
    width = std::sqrt(abcQuantile(m->b, m->c, 4.0, q));  // d = |D_P|
  } else if (const auto* m = brdf.as<Ggx>()) {
    width = 2.0 * std::atan(m->alpha * std::sqrt(q / (1.0 - q)));  // D cos θ_h: P(tan²θ_h ≤ t) = t/(α² + t)
  } else if (const auto* m = brdf.as<Ward>()) {
    width = 2.0 * std::atan(m->alpha * std::sqrt(-std::log(1.0 - q)));  // tan² θ_h = −α² ln(1 − ξ)
  } else if (const auto* m = brdf.as<WardDuer>()) {
    width = 2.0 * std::atan(m->alpha * std::sqrt(-std::log(1.0 - q)));
  } else if (const auto* m = brdf.as<NganCookTorrance>()) {
    width = 2.0 * std::atan(m->m * std::sqrt(-std::log(1.0 - q)));
  } else if (const auto* m = brdf.as<BlinnPhong>()) {
    width = 2.0 * std::acos(std::pow(1.0 - q, 1.0 / (m->n + 1.0)));  // cos θ_h = ξ^(1/(n+1))
  } else if (const auto* m = brdf.as<NganAshikhminShirley>()) {
    width = 2.0 * std::acos(std::pow(1.0 - q, 1.0 / (m->n + 1.0)));
  } else if (const auto* m = brdf.as<Sgd>()) {
    // The broadest channel's quantile, from the proposal's table (close to D cos θ_h's own).
    double tan2 = 0.0;
    for (int ch = 0; ch < 3; ++ch)
      if (m->channelWeight[ch] > 0.0) tan2 = std::max(tan2, m->tables[ch].sampleTan2(q));
    width = 2.0 * std::atan(std::sqrt(tan2));
  } else if (const auto* m = brdf.as<Lafortune>()) {
    width = std::acos(std::pow(1.0 - q, 1.0 / (m->n + 1.0)));  // about the lobe's axis, not the half vector
  }
  return std::clamp(width, 1e-5, 0.5);
}

LobeGrid gridFor(const Brdf& brdf, const Vec3& V) {
  return LobeGrid(Vec3(-V.x, -V.y, V.z), lobeWidth(brdf), 32, 32);
}

SamplingCheck checkSampler(const Brdf& brdf, const Vec3& V, const Chi2Grid& grid, long samples, unsigned seed,
                           double alpha) {
  SamplingCheck check;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const DirectionSampler draw = [&](std::mt19937_64& rng) -> std::optional<Vec3> {
    const double lobe = u(rng), u1 = u(rng), u2 = u(rng);
    const BrdfSample s = sample(brdf, V, lobe, Vec2(u1, u2));
    if (!s.valid()) return std::nullopt;
    const double p = pdf(brdf, s.L, V);
    const Rgb expected = eval(brdf, s.L, V) * (s.L.z / s.pdf);
    bool ok = std::abs(p - s.pdf) <= 1e-12 * s.pdf;
    for (int k = 0; k < 3; ++k) ok = ok && std::abs(s.weight[k] - expected[k]) <= 1e-9 * std::max(1.0, expected[k]);
    check.weightMismatches += !ok;
    return s.L;
  };
  const DirectionPdf density = [&](const Vec3& L) { return pdf(brdf, L, V); };
  check.chi2 = chi2Test(draw, density, grid, samples, seed, alpha);
  return check;
}

SamplingCheck checkSampler(const SamplingCase& c, long samples, unsigned seed, double alpha) {
  const Vec3 V = viewDirection(c.thetaV);
  return checkSampler(c.fit.brdf, V, gridFor(c.fit.brdf, V), samples, seed, alpha);
}

const std::vector<SamplingCase>& analyticChi2Family() {
  static const std::vector<SamplingCase> cases = [] {
    std::vector<SamplingCase> all;
    for (const auto& fits : {supplementFits(), extremeFits()})
      for (const LibraryFit& f : fits)
        for (const SamplingCase& c : atViewAngles(f)) all.push_back(c);
    for (const SamplingCase& c : atViewAngles({"lambertian", Lambertian{Rgb(0.5)}})) all.push_back(c);
    for (const auto& fits : {ggxChi2Fits(), publishedLobeChi2Fits()})
      for (const LibraryFit& f : fits)
        for (const SamplingCase& c : atViewAngles(f)) all.push_back(c);
    return all;
  }();
  return cases;
}

double chi2TestAlpha() { return sidakAlpha(kChi2FamilyAlpha, int(analyticChi2Family().size()) + kMeasuredChi2Tests); }

}  // namespace glossy::test
