// The spec's reference directional albedos (models.md: ∫ρ cos θ_L dω_L at V = N, red channel) reproduced
// by quadrature. The issue asks for 1e-3; the table is printed to 4 decimals, so hold it to its rounding.
#include "materials/models/albedo.h"
#include "materials/models/warp.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

#include <random>

namespace glossy::test {

struct AlbedoReference {
  const char* material;
  const char* fit;
  double red;
};

class ReferenceAlbedo : public ::testing::TestWithParam<AlbedoReference> {};

TEST_P(ReferenceAlbedo, QuadratureMatchesSpecTable) {
  const AlbedoReference& ref = GetParam();
  const MaterialFile m = loadMaterialFile(materialsDir() / (std::string(ref.material) + ".toml"));
  const Fit* fit = m.find(FitId::parse(ref.fit, "test"));
  ASSERT_NE(fit, nullptr);
  const double red = albedoAtNormalIncidence(makeBrdf(*fit)).r;
  EXPECT_NEAR(red, ref.red, 0.5e-4 + 1e-9) << ref.material << " " << ref.fit;
}

INSTANTIATE_TEST_SUITE_P(
    SpecTable, ReferenceAlbedo,
    ::testing::Values(AlbedoReference{"aluminium", "microfacet:E2", 0.1473}, AlbedoReference{"aluminium", "smooth:E2", 0.1546},
                      AlbedoReference{"aluminium", "ashikhmin-shirley:E2", 0.1057}, AlbedoReference{"aluminium", "cook-torrance:E2", 0.1053},
                      AlbedoReference{"aluminium", "cook-torrance:E1", 0.1161}, AlbedoReference{"aluminium", "ashikhmin-shirley:E1", 0.1167},
                      AlbedoReference{"black-obsidian", "microfacet:E2", 0.0088}, AlbedoReference{"black-obsidian", "smooth:E2", 0.0077},
                      AlbedoReference{"black-obsidian", "ashikhmin-shirley:E2", 0.0075}, AlbedoReference{"black-obsidian", "cook-torrance:E2", 0.0075},
                      AlbedoReference{"black-obsidian", "cook-torrance:E1", 0.0095}, AlbedoReference{"black-obsidian", "ashikhmin-shirley:E1", 0.0095},
                      AlbedoReference{"alum-bronze", "microfacet:E2", 0.1176}, AlbedoReference{"alum-bronze", "smooth:E2", 0.1217},
                      AlbedoReference{"alum-bronze", "ashikhmin-shirley:E2", 0.1182}, AlbedoReference{"alum-bronze", "cook-torrance:E2", 0.1174},
                      AlbedoReference{"alum-bronze", "cook-torrance:E1", 0.1147}, AlbedoReference{"alum-bronze", "ashikhmin-shirley:E1", 0.1147}),
    [](const auto& info) {
      std::string s = std::string(info.param.material) + "_" + info.param.fit;
      for (char& c : s)
        if (!isalnum(static_cast<unsigned char>(c))) c = '_';
      return s;
    });

// The quadrature itself, on lobes with known integrals.
TEST(Albedo, QuadratureIsExactForLambertian) {
  const Rgb a = albedoAtNormalIncidence(Lambertian{Rgb(0.25, 0.5, 1.0)});
  EXPECT_NEAR(a.r, 0.25, 1e-13);
  EXPECT_NEAR(a.g, 0.5, 1e-13);
  EXPECT_NEAR(a.b, 1.0, 1e-13);
}

TEST(Albedo, QuadratureResolvesTheNarrowestPublishedLobes) {
  // AS with n = 6.2e5 (the largest published exponent) has a lobe ~3 mrad wide at V = N; a midpoint rule in θ
  // far finer than that is the independent reference.
  const AshikhminShirley as{Rgb(0.0), Rgb(1.0), 6.2e5, 99.999};
  const double quad = albedoAtNormalIncidence(as).r;
  const int n = 4'000'000;
  double sum = 0.0;
  const double dt = 0.05 / n;  // the lobe is ~3 mrad wide; beyond 0.05 rad it is < 1e-300
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * dt;
    const Vec3 L(std::sin(t), 0.0, std::cos(t));
    sum += as.eval(L, Vec3(0, 0, 1)).r * std::cos(t) * std::sin(t) * dt;
  }
  EXPECT_NEAR(quad, 2.0 * kPi * sum, 1e-7 * quad);
}

}  // namespace glossy::test
