// glTF KHR_lights_punctual lights (renderer/lights/point_light.cpp, spot_light.cpp,
// directional_light.cpp): loaded with their nodes' transforms, refused when malformed, and rendered
// against analytic irradiance on a Lambertian floor, radiance = albedo/π · E, with a point light
// (E = I cos θ / r²), a spot across its cone's edge, a directional light (E = illuminance · cos θ), and a
// point light with an environment, whose MIS weights must leave the sum unbiased.
#include "materials/core/input_error.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/scene/scene.h"
#include "tests/support/gltf_doc.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/test_support.h"
#include "tests/support/tracer_comparison.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <tuple>

namespace glossy::test {

namespace {

using nlohmann::json;

constexpr double kAlbedo = 0.5;
constexpr int kSize = 40;  // pixels; the camera sees x, z in [−2, 2] of the floor y = 0 from above

// A Lambertian floor of albedo 0.5 and the given lights.
SceneDescription floorWith(std::vector<SceneLight> lights) {
  SceneDescription d;
  d.materials = {material("floor")};
  d.meshes.push_back(quad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 0));
  d.lights = std::move(lights);
  return d;
}

SceneLight light(const char* type, Rgb intensity, Vec3 position, Vec3 direction = {0, -1, 0}) {
  SceneLight l;
  l.name = type;
  l.type = type;
  l.intensity = intensity;
  l.position = position;
  l.direction = direction;
  return l;
}

RgbImage renderFloor(const SceneDescription& d, const Environment* environment, int spp, uint32_t seed, bool reference = false) {
  const EmbreeScene bvh(d);
  const RenderScene scene{&d, &bvh, {Lambertian{Rgb(kAlbedo)}}, Lambertian{Rgb(0.5)}, environment};
  RenderSettings s;
  s.width = s.height = kSize;
  s.spp = spp;
  s.seed = seed;
  s.threads = 2;
  s.progress = false;
  s.maxDepth = 2;  // direct light only: the floor sees nothing else
  s.reference = reference;
  RenderStats stats;
  return render(scene, orthographicDown(2.0, {0, 5, 0}, {0, 0, 0}, {0, 0, -1}), s, stats);
}

// The floor point seen at film position (px, py), in pixels.
Vec3 floorPoint(double px, double py) { return {(2.0 * px / kSize - 1.0) * 2.0, 0.0, -(1.0 - 2.0 * py / kSize) * 2.0}; }

// The mean of f over pixel (x, y)'s floor, by an 8 × 8 midpoint rule.
double pixelMean(int x, int y, const std::function<double(const Vec3&)>& f) {
  double sum = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) sum += f(floorPoint(x + (i + 0.5) / 8, y + (j + 0.5) / 8));
  return sum / 64;
}

// Every pixel's channels against albedo/π · E(p) · colour, within a relative tolerance plus `floor`.
void expectRadiance(const RgbImage& image, const Rgb& colour, const std::function<double(const Vec3&)>& irradiance,
                    double tolerance, double floor = 1e-6) {
  int checked = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const double e = pixelMean(x, y, irradiance) * kAlbedo / kPi;
      for (int c = 0; c < 3; ++c) {
        const double want = e * colour[c];
        ASSERT_NEAR(image.at(x, y)[c], want, tolerance * want + floor) << "pixel " << x << ", " << y << " channel " << c;
        ++checked;
      }
    }
  EXPECT_EQ(checked, kSize * kSize * 3);
}

// I cos θ / r² from a point at `at` onto the floor (normal +Y).
double pointIrradiance(const Vec3& at, const Vec3& p) {
  const Vec3 d = at - p;
  const double r2 = glm::dot(d, d);
  return d.y / std::sqrt(r2) / r2;
}

double spotFalloff(double cosTheta, double inner, double outer) {
  const double t = std::clamp((cosTheta - std::cos(outer)) / (std::cos(inner) - std::cos(outer)), 0.0, 1.0);
  return t * t;
}

}  // namespace

// A delta light's value is exact at every point, so the image is exact up to the film's integration over
// each pixel (64 stratified samples against the 8 × 8 rule: well under 1 %).
TEST(PunctualLights, APointLightOverAFloorGivesICosThetaOverRSquared) {
  const Rgb intensity(3.0, 2.0, 1.0);
  const Vec3 at(0.3, 1.0, -0.2);
  const SceneDescription d = floorWith({light("point", intensity, at)});
  expectRadiance(renderFloor(d, nullptr, 64, 1), intensity, [&](const Vec3& p) { return pointIrradiance(at, p); }, 0.01);
}

TEST(PunctualLights, ASpotFallsOffAsTheExtensionSaysAcrossItsConesEdge) {
  const Rgb intensity(2.0, 4.0, 1.0);
  const Vec3 at(0.0, 1.0, 0.0), axis = glm::normalize(Vec3(0.3, -1.0, 0.0));
  SceneLight spot = light("spot", intensity, at, axis);
  spot.innerConeAngle = 0.4;
  spot.outerConeAngle = 0.8;  // the edge crosses the floor at about 0.4 to 1.6 m from the axis's foot
  const RgbImage image = renderFloor(floorWith({spot}), nullptr, 64, 1);
  const auto e = [&](const Vec3& p) {
    return pointIrradiance(at, p) * spotFalloff(glm::dot(glm::normalize(p - at), axis), 0.4, 0.8);
  };
  expectRadiance(image, intensity, e, 0.02, 2e-3);
  // Not vacuous: the image holds the full cone, its falloff and the dark beyond.
  int full = 0, partial = 0, dark = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const Vec3 p = floorPoint(x + 0.5, y + 0.5);
      const double f = spotFalloff(glm::dot(glm::normalize(p - at), axis), 0.4, 0.8);
      full += f == 1.0, partial += f > 0.1 && f < 0.9, dark += f == 0.0;
    }
  EXPECT_GT(full, 50);
  EXPECT_GT(partial, 50);
  EXPECT_GT(dark, 50);
}

TEST(PunctualLights, ADirectionalLightGivesIlluminanceTimesCosTheta) {
  const Rgb illuminance(1.0, 2.0, 3.0);
  const Vec3 direction = glm::normalize(Vec3(1.0, -2.0, 0.5));
  const SceneDescription d = floorWith({light("directional", illuminance, Vec3(0.0), direction)});
  expectRadiance(renderFloor(d, nullptr, 4, 1), illuminance, [&](const Vec3&) { return -direction.y; }, 1e-6);
}

// A point light and a constant sky: the sky is found by light and BSDF samples, weighted against each
// other, the point light only by its samples, at weight 1. A point light weighted like the sky would
// render too dark. Two seeds measure each pixel's noise; the summed error must be within 4 σ of it.
TEST(PunctualLights, APointLightWithAnEnvironmentStaysUnbiased) {
  const Rgb intensity(1.0, 1.5, 2.0), sky(0.3, 0.6, 0.9);
  const Vec3 at(0.0, 1.0, 0.0);
  const SceneDescription d = floorWith({light("point", intensity, at)});
  const Environment environment = Environment::constant(sky);
  const RgbImage a = renderFloor(d, &environment, 256, 1), b = renderFloor(d, &environment, 256, 2);
  for (int c = 0; c < 3; ++c) {
    double error = 0.0, variance = 0.0, total = 0.0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double want =
            kAlbedo / kPi * (intensity[c] * pixelMean(x, y, [&](const Vec3& p) { return pointIrradiance(at, p); }) + sky[c] * kPi);
        const double mean = 0.5 * (a.at(x, y)[c] + b.at(x, y)[c]), half = 0.5 * (a.at(x, y)[c] - b.at(x, y)[c]);
        error += mean - want;
        variance += half * half;
        total += want;
      }
    EXPECT_LT(std::abs(error), 4.0 * std::sqrt(variance) + 1e-4 * total) << "channel " << c << ": mean error " << error / (kSize * kSize);
  }
}

// The wave has the reference path tracer's expectation with delta lights too, block by block
// (tracer_comparison.h: within 4.5 standard errors; at these samples each 8 × 8 block's test catches a
// bias of 14 % with 99 % probability).
TEST(PunctualLights, TheWaveMatchesTheReferenceWithDeltaLights) {
  SceneLight spot = light("spot", Rgb(2.0), {0.5, 1.5, 0.0});
  spot.outerConeAngle = 0.6;
  const SceneDescription d = floorWith({light("point", Rgb(1.0, 0.5, 0.2), {0, 1, 0}), spot,
                                        light("directional", Rgb(0.5), {}, glm::normalize(Vec3(1, -1, 0)))});
  const Environment environment = Environment::constant(Rgb(0.2));
  std::vector<RgbImage> wave, reference;
  for (uint32_t r = 0; r < 4; ++r) {
    wave.push_back(renderFloor(d, &environment, 64, 10 + r));
    reference.push_back(renderFloor(d, &environment, 256, 20 + r, true));
  }
  const BlockCheck check = compareBlocks(wave, reference, 8);
  EXPECT_LT(check.worstZ, 4.5);
  EXPECT_GT(check.lit, 0);
  EXPECT_LE(check.worstDetectable, 0.2);
}

// ---- Loading ----

namespace {

// A box, and each of `lights` on a node with `nodes[i]` merged in.
GltfDoc boxWithLights(const json& lights, const std::vector<json>& nodes) {
  GltfDoc g;
  std::vector<int> roots = {g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))};
  g.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  g.doc["extensions"] = {{"KHR_lights_punctual", {{"lights", lights}}}};
  for (size_t i = 0; i < nodes.size(); ++i) {
    json node = {{"name", "Lamp" + std::to_string(i)}, {"extensions", {{"KHR_lights_punctual", {{"light", int(i)}}}}}};
    node.update(nodes[i]);
    roots.push_back(g.push("nodes", node));
  }
  g.setScene(roots);
  return g;
}

}  // namespace

TEST(PunctualLights, GltfLightsLoadWithTheirNodesTransforms) {
  const double s = std::sqrt(0.5);
  const GltfDoc g = boxWithLights(
      {{{"type", "point"}, {"name", "Bulb"}, {"intensity", 5.0}, {"color", {1.0, 0.5, 0.25}}},
       {{"type", "spot"}, {"intensity", 2.0}, {"spot", {{"innerConeAngle", 0.1}, {"outerConeAngle", 0.5}}}},
       {{"type", "directional"}, {"intensity", 3.0}}},
      {{{"translation", {1, 2, 3}}},
       {{"rotation", {-s, 0, 0, s}}, {"translation", {0, 4, 0}}},  // −90° about X: −Z turns to −Y
       {{"scale", {2, 2, 2}}}});
  TempDir dir;
  const SceneDescription d = loadGltf(g.writeExternal(dir, "lit"));
  ASSERT_EQ(d.lights.size(), 3u);
  EXPECT_EQ(d.lights[0].type, "point");
  EXPECT_NE(d.lights[0].name.find("Bulb"), std::string::npos) << d.lights[0].name;
  EXPECT_EQ(d.lights[0].intensity, Rgb(5.0, 2.5, 1.25));
  EXPECT_EQ(d.lights[0].position, Vec3(1, 2, 3));
  EXPECT_EQ(d.lights[1].type, "spot");
  EXPECT_EQ(d.lights[1].intensity, Rgb(2.0));
  EXPECT_NEAR(glm::length(d.lights[1].direction - Vec3(0, -1, 0)), 0.0, 1e-12);
  EXPECT_EQ(d.lights[1].position, Vec3(0, 4, 0));
  EXPECT_EQ(d.lights[1].innerConeAngle, 0.1);
  EXPECT_EQ(d.lights[1].outerConeAngle, 0.5);
  EXPECT_EQ(d.lights[2].type, "directional");
  EXPECT_EQ(d.lights[2].direction, Vec3(0, 0, -1));  // unit whatever the node's scale
}

TEST(PunctualLights, MalformedLightsExitTwoNamingTheFileAndTheLight) {
  const json point = {{"type", "point"}, {"name", "Bad"}};
  const auto with = [&](json change) {
    json l = point;
    l.update(change);
    return l;
  };
  const auto one = [](json l, json node = json::object()) { return boxWithLights(json::array({l}), {node}); };
  json spot = with({{"type", "spot"}, {"spot", {{"outerConeAngle", 0.4}}}});
  const std::vector<std::pair<std::string, GltfDoc>> cases = {
      {"negative intensity", one(with({{"intensity", -1.0}}))},
      {"infinite intensity", one(with({{"intensity", 12345.5}}))},  // 1e999 in the file
      {"negative colour", one(with({{"color", {1, -1, 1}}}))},
      {"two colours", one(with({{"color", {1, 1}}}))},
      {"unknown type", one(with({{"type", "area"}}))},
      {"outer cone beyond pi/2", one(with({{"type", "spot"}, {"spot", {{"outerConeAngle", 1.6}}}}))},
      {"inner beyond outer", one([&] { json l = spot; l["spot"]["innerConeAngle"] = 0.5; return l; }())},
      {"negative inner", one([&] { json l = spot; l["spot"]["innerConeAngle"] = -0.1; return l; }())},
      {"singular transform", one(point, {{"scale", {1, 0, 1}}})},
      {"light that does not exist", one(point, {{"extensions", {{"KHR_lights_punctual", {{"light", 7}}}}}})},
  };
  for (const auto& [what, g] : cases) {
    SCOPED_TRACE(what);
    TempDir dir;
    const std::filesystem::path scene = g.writeExternal(dir, "lamp");
    std::string text = readText(scene);  // JSON has no infinity: a number too large for a double gives it
    if (const size_t at = text.find("12345.5"); at != std::string::npos) writeText(scene, text.replace(at, 7, "1e999"));
    const RunResult r = runGlossy({"render", "--scene", scene.string(), "--width", "8", "--height", "8", "--spp", "1",
                                   "-o", (dir / "x.exr").string()});
    expectOneLineError(r, "lamp.gltf");
    // A number too large for a double stops at the JSON parser, before the loader's own check.
    expectOneLineError(r, what == "light that does not exist" ? "light 7" : what == "infinite intensity" ? "overflow" : "light 'Bad'");
    EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
  }
}

// A light's fields have physical bounds and the schema's types: colour × intensity beyond what the float
// image holds (alone, through its colour, or as one of several lights) is refused naming the light, as
// --env-constant's radiance is, never dropped to a black image or clipped at the largest float; a field of
// the wrong type is refused, never read as its default.
TEST(PunctualLights, LightsBeyondTheirBoundsOrWithFieldsOfTheWrongTypeAreRefused) {
  const json point = {{"type", "point"}, {"name", "Bad"}, {"intensity", 1.0}};
  const auto with = [&](json change) {
    json l = point;
    l.update(change);
    return l;
  };
  const json fine = {{"type", "point"}, {"name", "Fine"}, {"intensity", 2.0}};
  const std::vector<std::tuple<std::string, GltfDoc, std::string>> cases = {
      {"intensity 1e300", boxWithLights(json::array({with({{"intensity", 1e300}})}), {json::object()}), "color × intensity"},
      {"colour times intensity", boxWithLights(json::array({with({{"intensity", 1e7}, {"color", {1e7, 0, 0}}})}), {json::object()}), "color × intensity"},
      {"colour 1e200 times intensity 1e200",
       boxWithLights(json::array({with({{"intensity", 1e200}, {"color", {1, 1e200, 1}}})}), {json::object()}), "color × intensity"},
      {"two lights", boxWithLights(json::array({fine, with({{"intensity", 1e300}})}), {json::object(), json::object()}), "color × intensity"},
      {"intensity as text", boxWithLights(json::array({with({{"intensity", "1e300"}})}), {json::object()}), "intensity must be a number"},
      {"colour as text", boxWithLights(json::array({with({{"color", "red"}})}), {json::object()}), "color must be an array of three numbers"},
      {"colour of text", boxWithLights(json::array({with({{"color", {"1", 1, 1}}})}), {json::object()}), "color must be an array of three numbers"},
      {"type as a number", boxWithLights(json::array({with({{"type", 3}})}), {json::object()}), "type must be a string"},
      {"no type", boxWithLights(json::array({json{{"name", "Bad"}}}), {json::object()}), "has no type"},
      {"range as a bool", boxWithLights(json::array({with({{"range", true}})}), {json::object()}), "range must be a number"},
      {"spot as text", boxWithLights(json::array({with({{"type", "spot"}, {"spot", "wide"}})}), {json::object()}), "spot must be an object"},
      {"cone as text", boxWithLights(json::array({with({{"type", "spot"}, {"spot", {{"outerConeAngle", "0.5"}}}})}), {json::object()}),
       "spot.outerConeAngle must be a number"},
  };
  for (const auto& [what, g, why] : cases) {
    SCOPED_TRACE(what);
    TempDir dir;
    const std::filesystem::path scene = g.writeExternal(dir, "lamp");
    for (const char* command : {"render", "sheet"}) {
      std::vector<std::string> args{command, "--scene", scene.string(), "--width", "8", "--height", "8", "--spp", "1"};
      if (std::string(command) == "sheet") args.insert(args.end(), {"--material", (materialsDir() / "chrome.toml").string()});
      args.insert(args.end(), {"-o", (dir / "x.exr").string()});
      const RunResult r = runGlossy(args);
      expectOneLineError(r, "lamp.gltf");
      expectOneLineError(r, "light 'Bad'");
      expectOneLineError(r, why);
      EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
    }
  }
  // The bound itself is a light glossy renders, finite.
  TempDir dir;
  const std::filesystem::path scene = boxWithLights(json::array({with({{"intensity", 1e12}})}), {json::object()}).writeExternal(dir, "lamp");
  const RunResult r = runGlossy({"render", "--scene", scene.string(), "--width", "8", "--height", "8", "--spp", "1", "-o", (dir / "x.exr").string()});
  EXPECT_EQ(r.status, 0) << r.err;
}

}  // namespace glossy::test
