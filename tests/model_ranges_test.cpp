// Every model's declared parameter ranges keep it finite: at every corner of the box the ranges span
// (each parameter at its lowest or highest accepted value), eval, sample and pdf are finite for a spread of
// directions, and a value just outside a range is refused by the file loader naming file, line and key.
// The loop runs over the registry, so a new model is checked without a new test.
#include "materials/models/brdf.h"
#include "materials/models/registry.h"
#include "materials/params/material_file.h"
#include "materials/core/text.h"
#include "tests/support/test_support.h"

#include <cmath>
#include <vector>

namespace glossy::test {

namespace {

bool finite(const Rgb& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

Vec3 dir(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// Directions from the pole to grazing, the mirror pair included (θ of V and L equal, φ opposite).
std::vector<Vec3> directions() {
  std::vector<Vec3> out;
  for (double theta : {0.0, 1e-6, 0.3, 0.8, 1.2, 1.5, M_PI / 2 - 1e-6})
    for (double phi : {0.0, 0.7, M_PI, 4.0}) out.push_back(dir(theta, phi));
  return out;
}

// Each range's ends, per parameter (choices take their first).
std::vector<ParamSet> corners(const ModelInfo& model) {
  std::vector<ParamSet> sets(1);
  for (const ParamSpec& spec : model.params) {
    if (spec.kind == ParamKind::Choice) {
      for (ParamSet& s : sets) s.set(std::string(spec.key), std::string(spec.choices.front()));
      continue;
    }
    std::vector<ParamSet> next;
    for (const ParamSet& s : sets)
      for (double v : {spec.range.lo, spec.range.hi}) {
        ParamSet t = s;
        if (spec.kind == ParamKind::Rgb) t.set(std::string(spec.key), Rgb(v));
        else t.set(std::string(spec.key), v);
        next.push_back(std::move(t));
      }
    sets = std::move(next);
  }
  return sets;
}

std::string describe(const ModelInfo& model, const ParamSet& p) {
  std::string s(model.name);
  for (const ParamSpec& spec : model.params) {
    const ParamSet::Value* v = p.find(spec.key);
    s.append(" ").append(spec.key).append("=");
    if (std::holds_alternative<double>(*v)) s += formatted("%g", std::get<double>(*v));
    else if (std::holds_alternative<Rgb>(*v)) s += formatted("%g", std::get<Rgb>(*v).r);
    else s += std::get<std::string>(*v);
  }
  return s;
}

}  // namespace

TEST(ModelRanges, EveryRangeIsFiniteAndBounded) {
  for (const ModelInfo& model : analyticModels())
    for (const ParamSpec& spec : model.params) {
      if (spec.kind == ParamKind::Choice) continue;
      EXPECT_TRUE(std::isfinite(spec.range.lo) && std::isfinite(spec.range.hi) && spec.range.lo <= spec.range.hi)
          << model.name << " " << spec.key;
      // A parameter of a BRDF has no business beyond ±1e9; the loose default range means one was forgotten.
      // Save SGD's shadowing rate c, which Bagher et al.'s published fits take up to 1.6e109 (chrome-steel).
      const bool publishedBeyond = model.name == "sgd" && spec.key == "c";
      EXPECT_LE(spec.range.hi, publishedBeyond ? 1e300 : 1e9) << model.name << " " << spec.key;
      EXPECT_GE(spec.range.lo, -1e9) << model.name << " " << spec.key;
    }
}

TEST(ModelRanges, ModelsAreFiniteAtTheEndsOfTheirRanges) {
  const std::vector<Vec3> dirs = directions();
  const double us[] = {0.0, 1e-9, 0.25, 0.5, 0.75, 1.0 - 1e-9};
  for (const ModelInfo& model : analyticModels()) {
    for (const ParamSet& params : corners(model)) {
      const Brdf brdf = model.make(params);
      int bad = 0;
      for (const Vec3& V : dirs) {
        if (V.z <= 0.0) continue;
        for (const Vec3& L : dirs) {
          const Rgb f = eval(brdf, L, V);
          const double p = pdf(brdf, L, V);
          if (!finite(f) || !std::isfinite(p)) ++bad;
          const Vec3 mirror{-V.x, -V.y, V.z};
          if (!finite(eval(brdf, mirror, V)) || !std::isfinite(pdf(brdf, mirror, V))) ++bad;
        }
        for (double uLobe : us)
          for (double u0 : us)
            for (double u1 : us) {
              const BrdfSample s = sample(brdf, V, uLobe, {u0, u1});
              if (!std::isfinite(s.pdf) || !finite(s.weight) || !std::isfinite(s.L.x) || !std::isfinite(s.L.y) ||
                  !std::isfinite(s.L.z))
                ++bad;
            }
      }
      EXPECT_EQ(bad, 0) << describe(model, params);
    }
  }
}

TEST(ModelRanges, FileValuesOutsideARangeAreRefusedNamingFileLineAndKey) {
  TempDir dir;
  const std::filesystem::path file = dir / "tiny-m.toml";
  // Values a "positive" check lets through and that evaluate to NaN.
  for (const std::string bad : {"m = 1e-308", "m = 5e-324", "eta = 1e308", "m = 11.0"}) {
    std::string text = "name = \"tiny-m\"\n\n[[fit]]\nmodel = \"cook-torrance\"\nmetric = \"E2\"\n"
                       "kd = [0.1, 0.1, 0.1]\nks = [0.5, 0.5, 0.5]\n";
    text += bad.starts_with("m ") ? bad + "\neta = 1.5\n" : "m = 0.1\n" + bad + "\n";
    writeText(file, text);
    const std::string message = expectInputError([&] { loadMaterialFile(file); });
    const std::string key = bad.substr(0, bad.find(' '));
    const std::string line = bad.starts_with("m ") ? ":8" : ":9";
    EXPECT_NE(message.find(file.string() + line), std::string::npos) << message;
    EXPECT_NE(message.find("'" + key + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("must be in ["), std::string::npos) << message;
    expectOneLineError(runGlossy({"eval", "--material", file.string(), "--fit", "cook-torrance:E2"}, "0,0,1,0,0,1\n"),
                       file.string());
  }
}

}  // namespace glossy::test
