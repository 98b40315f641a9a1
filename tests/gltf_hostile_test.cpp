// Hostile glTF input through the loader and the command line: camera and mesh transforms that are singular
// or overflow (which used to abort inside Embree), and the conformance refusals (required extensions,
// version, scene index, unparseable JSON) and warnings (emissive textures).
#include "materials/core/input_error.h"
#include "renderer/image/exr_image.h"
#include "renderer/scene/scene.h"
#include "tests/support/gltf_doc.h"
#include "tests/support/test_support.h"

#include <algorithm>
#include <cmath>

namespace glossy::test {

namespace {

using nlohmann::json;

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

// A box at the origin, and a camera node named CamNode 4 m in front of it with `camNode` merged in; when
// `parent` is given the camera hangs under a node named Rig with those properties.
GltfDoc boxWithCamera(const json& camNode, const json& parent = nullptr) {
  GltfDoc g;
  const int box = g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}));
  g.doc["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.1}}}}});
  json cam = {{"name", "CamNode"}, {"camera", 0}, {"translation", {0, 0, 4}}};
  cam.update(camNode);
  const int camera = g.push("nodes", cam);
  if (parent.is_null()) {
    g.setScene({box, camera});
  } else {
    json rig = parent;
    rig["name"] = "Rig";
    rig["children"] = {camera};
    g.setScene({box, g.push("nodes", rig)});
  }
  return g;
}

std::vector<std::string> renderArgs(const std::filesystem::path& scene, const std::filesystem::path& out) {
  return {"render", "--scene", scene.string(), "--width", "16", "--height", "16", "--spp", "1", "--env-constant", "1",
          "-o", out.string()};
}

bool allFinite(const RgbImage& image) {
  return std::all_of(image.pixels.begin(), image.pixels.end(), [](float v) { return std::isfinite(v); });
}

}  // namespace

// ---- Camera and mesh transforms ----

TEST(GltfHostileTransforms, DegenerateCamerasExitTwoNamingTheNodeInRenderAndSheet) {
  const std::vector<std::pair<std::string, GltfDoc>> cases = {
      {"scale 0", boxWithCamera({{"scale", {0, 0, 0}}})},
      {"zero matrix", boxWithCamera({{"translation", nullptr}, {"matrix", std::vector<double>(16, 0.0)}})},
      {"zero linear part", boxWithCamera({{"translation", nullptr},
                                          {"matrix", {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 4, 1}}})},
      {"translation 3e38", boxWithCamera({{"translation", {0, 0, 3e38}}})},
      {"parent scale 0", boxWithCamera(json::object(), {{"scale", {0, 0, 0}}})},
      {"flattened parent", boxWithCamera(json::object(), {{"scale", {1, 0, 1}}})},
  };
  TempDir dir;
  for (const auto& [what, doc] : cases) {
    SCOPED_TRACE(what);
    GltfDoc g = doc;
    // json::update leaves a null where a key was cleared; glTF has no nulls.
    for (json& n : g.doc["nodes"])
      if (n.contains("translation") && n["translation"].is_null()) n.erase("translation");
    const auto path = g.writeExternal(dir, "camera");
    const RunResult r = runGlossy(renderArgs(path, dir / "x.exr"));
    expectOneLineError(r, "CamNode");
    EXPECT_FALSE(std::filesystem::exists(dir / "x.exr"));
    expectOneLineError(runGlossy({"sheet", "--scene", path.string(), "--material", (materialsDir() / "chrome.toml").string(),
                                  "--width", "8", "--height", "8", "--spp", "1", "-o", (dir / "s.exr").string()}),
                       "CamNode");
  }
}

TEST(GltfHostileTransforms, TinyAndHugeCameraScalesStillGiveFiniteRays) {
  TempDir dir;
  for (double s : {1e-200, 1e-30, 1e30, 1e200}) {
    SCOPED_TRACE(s);
    const auto path = boxWithCamera({{"scale", {s, s, s}}}).writeExternal(dir, "scaled");
    const RunResult r = runGlossy(renderArgs(path, dir / "x.exr"));
    ASSERT_EQ(r.status, 0) << r.err;
    const RgbImage image = readRgbImage(dir / "x.exr");
    EXPECT_TRUE(allFinite(image));
    EXPECT_LT(image.pixels[3 * (8 * 16 + 8)], 0.99f);  // the box, in the middle, is darker than the sky
  }
}

TEST(GltfHostileTransforms, MeshUnderScaleZeroIsSkippedWithOneWarning) {
  GltfDoc g;
  const int visible = g.addMeshNode("Visible", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}));
  const int hidden = g.addMeshNode("Hidden", boxPrimitive(g, {3, 0, 0}, {1, 1, 1}), {{"scale", {0, 0, 0}}});
  const int flat = g.addMeshNode("Flat", boxPrimitive(g, {-3, 0, 0}, {1, 1, 1}), {{"scale", {1, 1, 0}}});
  g.setScene({visible, hidden, flat});
  TempDir dir;
  const RunResult r = runGlossy(renderArgs(g.writeExternal(dir, "hidden"), dir / "x.exr"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(r.err, "glossy: ");
  EXPECT_CONTAINS(r.err, "HiddenNode");
  EXPECT_EQ(r.err.find("FlatNode"), std::string::npos) << r.err;
  EXPECT_TRUE(allFinite(readRgbImage(dir / "x.exr")));

  // The box flattened along z keeps its two z faces as a card; the one scaled to 0 is gone.
  const SceneDescription s = loadGltf(dir / "hidden.gltf");
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_CONTAINS(s.meshes[0].name, "Visible");
  EXPECT_CONTAINS(s.meshes[1].name, "Flat");
  EXPECT_EQ(s.meshes[1].indices.size(), 12u);
}

TEST(GltfHostileTransforms, MeshBeyondEmbreesRangeExitsTwoNamingTheNode) {
  for (const json& node : {json{{"translation", {3e38, 0, 0}}}, json{{"scale", {1e30, 1e30, 1e30}}}}) {
    SCOPED_TRACE(node.dump());
    GltfDoc g;
    g.setScene({g.addMeshNode("Far", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}), node)});
    TempDir dir;
    expectOneLineError(runGlossy(renderArgs(g.writeExternal(dir, "far"), dir / "x.exr")), "FarNode");
  }
  // Only a mesh under a singular transform is skipped: when it is all there is, the scene is refused.
  GltfDoc g;
  g.setScene({g.addMeshNode("Gone", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}), {{"scale", {0, 0, 0}}})});
  TempDir dir;
  expectOneLineError(runGlossy(renderArgs(g.writeExternal(dir, "gone"), dir / "x.exr")), "no triangle meshes");
}

// ---- Conformance ----

TEST(GltfConformance, UnsupportedRequiredExtensionIsTheFirstErrorNamed) {
  TempDir dir;
  for (const std::string ext : {"KHR_draco_mesh_compression", "KHR_materials_pbrSpecularGlossiness", "EXT_made_up"}) {
    SCOPED_TRACE(ext);
    GltfDoc g;
    g.setScene({g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))});
    g.doc["extensionsUsed"] = {ext};
    g.doc["extensionsRequired"] = {"KHR_materials_emissive_strength", ext};
    // Whatever else is wrong with the file comes second: a compressed mesh's accessors often have no data.
    g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99;
    g.doc["asset"]["version"] = "1.0";
    const auto gltf = g.writeExternal(dir, "compressed");
    std::filesystem::remove(dir / "compressed.bin");
    const std::string e = expectInputError([&] { loadGltf(gltf); });
    EXPECT_CONTAINS(e, "compressed.gltf");
    EXPECT_CONTAINS(e, ext);
    EXPECT_EQ(e.find("1.0"), std::string::npos) << e;
    const RunResult r = runGlossy(renderArgs(g.writeGlb(dir, "compressed"), dir / "x.exr"));
    expectOneLineError(r, ext);
    EXPECT_CONTAINS(r.err, "compressed.glb");
  }
}

TEST(GltfConformance, SupportedRequiredExtensionsLoad) {
  GltfDoc g;
  g.setScene({g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))});
  g.doc["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_texture_transform"};
  g.doc["extensionsRequired"] = {"KHR_materials_emissive_strength", "KHR_texture_transform"};
  TempDir dir;
  EXPECT_EQ(loadGltf(g.writeExternal(dir, "ok")).meshes.size(), 1u);
}

TEST(GltfConformance, VersionOtherThanTwoIsRefused) {
  TempDir dir;
  for (const std::string version : {"1.0", "3.0", "two"}) {
    GltfDoc g;
    g.setScene({g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))});
    g.doc["asset"]["version"] = version;
    const RunResult r = runGlossy(renderArgs(g.writeExternal(dir, "old"), dir / "x.exr"));
    expectOneLineError(r, "asset.version is '" + version + "'");
    EXPECT_CONTAINS(r.err, "old.gltf");
  }
  GltfDoc g;
  g.setScene({g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))});
  g.doc["asset"]["version"] = "2.1";  // a later minor version stays readable
  EXPECT_EQ(loadGltf(g.writeExternal(dir, "minor")).meshes.size(), 1u);
}

TEST(GltfConformance, SceneIndexOutOfRangeIsRefused) {
  TempDir dir;
  for (int scene : {1, 7, -2}) {
    GltfDoc g;
    g.setScene({g.addMeshNode("Box", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))});
    g.doc["scene"] = scene;
    const RunResult r = runGlossy(renderArgs(g.writeExternal(dir, "scenes"), dir / "x.exr"));
    expectOneLineError(r, "scene " + std::to_string(scene));
    EXPECT_CONTAINS(r.err, "scenes.gltf");
  }
}

TEST(GltfConformance, ParseErrorsAreOnePrintableLine) {
  TempDir dir;
  std::string garbage = "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [\x01\x02\xff\xfe\x80\n\n\x1b[31m";
  for (int i = 0; i < 4000; ++i) garbage += char((i * 73 + 11) % 256);
  writeText(dir / "garbage.gltf", garbage);
  // A GLB whose JSON chunk is binary.
  std::string glb = std::string("glTF\x02\0\0\0", 8) + std::string(4, '\0') + std::string("\x00\x01\0\0JSON", 8) +
                    garbage.substr(60, 256);
  writeText(dir / "garbage.glb", glb);
  for (const char* name : {"garbage.gltf", "garbage.glb"}) {
    SCOPED_TRACE(name);
    const RunResult r = runGlossy(renderArgs(dir / name, dir / "x.exr"));
    expectOneLineError(r, name);
    EXPECT_LT(r.err.size(), 500u) << r.err;
    for (char c : r.err.substr(0, r.err.size() - 1)) {
      const auto b = static_cast<unsigned char>(c);  // no control characters, no bytes UTF-8 never uses
      EXPECT_TRUE(b >= 0x20 && b != 0x7f && b != 0xfe && b != 0xff) << int(b) << " in " << r.err;
    }
  }
}

TEST(GltfConformance, EmissiveTexturesWarnOnceAndEmitNothing) {
  GltfDoc g;
  g.doc["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgo="}}};
  g.doc["textures"] = {{{"source", 0}}};
  g.doc["materials"] = {{{"name", "lamp"}, {"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", 0}}}},
                        {{"name", "screen"}, {"emissiveFactor", {1, 0.5, 1}}, {"emissiveTexture", {{"index", 0}}}},
                        {{"name", "glow"}, {"emissiveFactor", {2, 2, 2}}}};
  json a = boxPrimitive(g, {0, 0, 0}, {1, 1, 1}), b = boxPrimitive(g, {2, 0, 0}, {1, 1, 1}),
       c = boxPrimitive(g, {-2, 0, 0}, {1, 1, 1});
  a["material"] = 0;
  b["material"] = 1;
  c["material"] = 2;
  g.setScene({g.addMeshNode("A", a), g.addMeshNode("B", b), g.addMeshNode("C", c)});
  TempDir dir;
  const auto path = g.writeExternal(dir, "emissive");
  const SceneDescription s = loadGltf(path);
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_FALSE(s.materials[0].isEmissive());
  EXPECT_FALSE(s.materials[1].isEmissive());
  EXPECT_TRUE(s.materials[2].isEmissive());  // no texture: its factor is the whole emission

  const RunResult r = runGlossy(renderArgs(path, dir / "x.exr"));
  ASSERT_EQ(r.status, 0) << r.err;
  size_t lines = 0;
  for (size_t at = r.err.find("emissive texture"); at != std::string::npos; at = r.err.find("emissive texture", at + 1)) ++lines;
  EXPECT_EQ(lines, 1u) << r.err;
  EXPECT_NE(r.err.find("glossy: "), std::string::npos) << r.err;
  EXPECT_CONTAINS(r.err, "'lamp'");
  EXPECT_CONTAINS(r.err, "'screen'");
}

}  // namespace glossy::test
