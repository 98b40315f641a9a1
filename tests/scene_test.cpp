// The glTF loader and the Embree scene on small glTF files written here (buffer layouts, index types,
// transforms, cameras, materials, malformed input), and on the committed scenes/sphere.gltf and
// scenes/preview.gltf.
#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "renderer/scene/embree_scene.h"
#include "renderer/scene/scene.h"
#include "tests/support/gltf_doc.h"
#include "tests/support/test_support.h"

#include <nlohmann/json.hpp>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

namespace glossy::test {

namespace {

using nlohmann::json;

constexpr int kLines = 1;

// The unit square in z = 0, facing +Z: triangles (0,1,2) and (0,2,3).
const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const std::vector<uint32_t> kQuadIndices = {0, 1, 2, 0, 2, 3};

GltfDoc quadDoc(bool withNormals = true) {
  GltfDoc g;
  json prim = {{"attributes", {{"POSITION", g.addPositions(kQuad)}}}, {"indices", g.addIndices(kQuadIndices)}};
  if (withNormals) prim["attributes"]["NORMAL"] = g.addPositions(std::vector<glm::vec3>(4, {0, 0, 1}));
  g.setScene({g.addMeshNode("Quad", prim)});
  return g;
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-6) {
  EXPECT_NEAR(a.x, b.x, tol) << "x";
  EXPECT_NEAR(a.y, b.y, tol) << "y";
  EXPECT_NEAR(a.z, b.z, tol) << "z";
}

Vec3 windingNormal(const Mesh& m, size_t triangle) {
  const Vec3 p0(m.positions[m.indices[3 * triangle]]), p1(m.positions[m.indices[3 * triangle + 1]]),
      p2(m.positions[m.indices[3 * triangle + 2]]);
  return glm::normalize(glm::cross(p1 - p0, p2 - p0));
}

void expectQuad(const SceneDescription& s) {
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  ASSERT_EQ(m.positions.size(), 4u);
  for (size_t i = 0; i < 4; ++i) expectNear(Vec3(m.positions[i]), Vec3(kQuad[i]), 0.0);
  EXPECT_EQ(m.indices, kQuadIndices);
  ASSERT_EQ(m.normals.size(), 4u);
  expectNear(Vec3(m.normals[2]), {0, 0, 1});
  EXPECT_EQ(m.material, -1);
  EXPECT_CONTAINS(m.name, "mesh 'Quad'");
  EXPECT_CONTAINS(m.name, "node 'QuadNode'");
  EXPECT_CONTAINS(m.name, "primitive 0");
}

// ---- Buffer layouts and index types ----

TEST(SceneLoader, ReadsExternalBuffer) {
  TempDir dir;
  const auto path = quadDoc().writeExternal(dir, "quad");
  const SceneDescription s = loadGltf(path);
  EXPECT_EQ(s.source, path);
  expectQuad(s);
}

TEST(SceneLoader, ReadsEmbeddedBuffer) {
  TempDir dir;
  expectQuad(loadGltf(quadDoc().writeEmbedded(dir, "quad")));
}

TEST(SceneLoader, ReadsGlb) {
  TempDir dir;
  expectQuad(loadGltf(quadDoc().writeGlb(dir, "quad")));
}

TEST(SceneLoader, ReadsEveryIndexType) {
  for (int type : {kUnsignedByte, kUnsignedShort, kUnsignedInt}) {
    SCOPED_TRACE(type);
    GltfDoc g;
    g.setScene({g.addMeshNode(
        "Quad", {{"attributes", {{"POSITION", g.addPositions(kQuad)}}}, {"indices", g.addIndices(kQuadIndices, type)}})});
    TempDir dir;
    const SceneDescription s = loadGltf(g.writeExternal(dir, "quad"));
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.meshes[0].indices, kQuadIndices);
    EXPECT_TRUE(s.meshes[0].normals.empty());
  }
}

TEST(SceneLoader, ExpandsNonIndexedTriangles) {
  GltfDoc g;
  const std::vector<glm::vec3> soup = {kQuad[0], kQuad[1], kQuad[2], kQuad[0], kQuad[2], kQuad[3]};
  g.setScene({g.addMeshNode("Soup", {{"attributes", {{"POSITION", g.addPositions(soup)}}}})});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "soup"));
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(s.meshes[0].positions.size(), 6u);
}

TEST(SceneLoader, RespectsByteOffsetAndByteStride) {
  // Interleaved position + normal records (stride 24) after 8 bytes of padding, indices after 2 unused ones.
  GltfDoc g;
  std::vector<float> interleaved(2, 9.0f);
  for (const glm::vec3& p : kQuad) interleaved.insert(interleaved.end(), {p.x, p.y, p.z, 0.0f, 0.6f, 0.8f});
  const int view = g.addView(bytesOf(interleaved), 24);
  const int positions = g.addAccessor(view, kFloat, "VEC3", 4, 8);
  const int normals = g.addAccessor(view, kFloat, "VEC3", 4, 20);
  std::vector<uint16_t> indices = {7, 7};
  indices.insert(indices.end(), kQuadIndices.begin(), kQuadIndices.end());
  const int idx = g.addAccessor(g.addView(bytesOf(indices)), kUnsignedShort, "SCALAR", 6, 4);
  g.setScene({g.addMeshNode(
      "Strided", {{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}, {"indices", idx}})});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "strided"));
  ASSERT_EQ(s.meshes.size(), 1u);
  for (size_t i = 0; i < 4; ++i) expectNear(Vec3(s.meshes[0].positions[i]), Vec3(kQuad[i]), 0.0);
  expectNear(Vec3(s.meshes[0].normals[3]), {0.0, 0.6, 0.8});
  EXPECT_EQ(s.meshes[0].indices, kQuadIndices);
}

// ---- Transforms ----

TEST(SceneLoader, ComposesNestedTransforms) {
  // matrix translate(0,5,0) → scale 2 → translate(1,0,0)·rotate 90° about +Y (which maps x ↦ −z, z ↦ x).
  GltfDoc g;
  const std::vector<glm::vec3> triangle = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double h = std::sqrt(0.5);
  const int child = g.addMeshNode("Tri", {{"attributes", {{"POSITION", g.addPositions(triangle)}}}},
                                  {{"translation", {1, 0, 0}}, {"rotation", {0, h, 0, h}}});
  const int scaled = g.push("nodes", {{"name", "Scaled"}, {"scale", {2, 2, 2}}, {"children", {child}}});
  const int moved = g.push("nodes", {{"name", "Moved"},
                                     {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1}},
                                     {"children", {scaled}}});
  g.setScene({moved});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "nested"));
  ASSERT_EQ(s.meshes.size(), 1u);
  const Mesh& m = s.meshes[0];
  expectNear(Vec3(m.positions[0]), {2, 5, -2});
  expectNear(Vec3(m.positions[1]), {2, 7, 0});
  expectNear(Vec3(m.positions[2]), {4, 5, 0});
  EXPECT_EQ(m.indices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(SceneLoader, UsesAllRootNodesWithoutAScene) {
  GltfDoc g = quadDoc();
  g.doc.erase("scenes");
  g.doc.erase("scene");
  g.addMeshNode("Second", {{"attributes", {{"POSITION", g.addPositions(kQuad)}}}, {"indices", g.addIndices(kQuadIndices)}},
                {{"translation", {0, 0, 3}}});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "noscene"));
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_FLOAT_EQ(s.meshes[1].positions[0].z, 3.0f);
}

TEST(SceneLoader, TransformsNormalsByInverseTranspose) {
  // Under a non-uniform scale (2, 1, 1) a 45° normal must tilt toward the stretched axis's plane.
  GltfDoc g;
  const std::vector<glm::vec3> triangle = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const float c = float(std::sqrt(1.0 / 3.0));
  json prim = {{"attributes",
                {{"POSITION", g.addPositions(triangle)}, {"NORMAL", g.addPositions(std::vector<glm::vec3>(3, {c, c, c}))}}}};
  g.setScene({g.addMeshNode("Tri", prim, {{"scale", {2, 1, 1}}})});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "stretched"));
  const Vec3 expected = glm::normalize(Vec3(0.5, 1.0, 1.0));
  expectNear(Vec3(s.meshes[0].normals[0]), expected);
  // Still perpendicular to the stretched triangle, which is what the inverse transpose is for.
  expectNear(windingNormal(s.meshes[0], 0), expected);
}

TEST(SceneLoader, MirroringTransformKeepsWindingAndNormalsAgreeing) {
  for (double flip : {1.0, -1.0}) {
    SCOPED_TRACE(flip);
    GltfDoc g = quadDoc();
    g.doc["nodes"][0]["scale"] = {1.0, 1.0, flip};
    g.doc["nodes"][0]["translation"] = {0.0, 0.0, flip};
    TempDir dir;
    const SceneDescription s = loadGltf(g.writeExternal(dir, "mirror"));
    const Mesh& m = s.meshes[0];
    for (size_t t = 0; t < 2; ++t) expectNear(windingNormal(m, t), {0, 0, flip});
    expectNear(Vec3(m.normals[0]), {0, 0, flip});
    EXPECT_FLOAT_EQ(m.positions[0].z, float(flip));
  }
}

// ---- Cameras and materials ----

TEST(SceneLoader, ReadsCamerasInNodeOrderWithWorldMatrices) {
  GltfDoc g = quadDoc();
  g.doc["cameras"] = {
      {{"type", "perspective"}, {"name", "Main"}, {"perspective", {{"yfov", 0.5}, {"aspectRatio", 1.5}, {"znear", 0.1}}}},
      {{"type", "orthographic"}, {"orthographic", {{"xmag", 2.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}},
      {{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}};
  const double h = std::sqrt(0.5);
  const int persp = g.push("nodes", {{"name", "MainNode"}, {"camera", 0}, {"translation", {0, 0, 3}}});
  const int ortho = g.push("nodes", {{"name", "Side"}, {"camera", 1}, {"translation", {0, 1, 0}}});
  const int rig = g.push("nodes", {{"name", "Rig"}, {"rotation", {0, h, 0, h}}, {"children", {ortho}}});
  const int plain = g.push("nodes", {{"camera", 2}});
  // Traversal meets the orthographic camera first; node order puts the perspective one first.
  g.setScene({rig, plain, 0, persp});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "cameras"));
  ASSERT_EQ(s.cameras.size(), 3u);

  const Camera& a = s.cameras[0];
  EXPECT_EQ(a.name, "Main");
  EXPECT_EQ(a.type, Camera::Type::Perspective);
  EXPECT_DOUBLE_EQ(a.yfov, 0.5);
  EXPECT_DOUBLE_EQ(a.aspectRatio, 1.5);
  expectNear(Vec3(a.cameraToWorld[3]), {0, 0, 3});
  expectNear(Vec3(a.cameraToWorld * glm::dvec4(0, 0, -1, 0)), {0, 0, -1});

  const Camera& b = s.cameras[1];
  EXPECT_EQ(b.name, "Side");  // unnamed camera: its node's name
  EXPECT_EQ(b.type, Camera::Type::Orthographic);
  EXPECT_DOUBLE_EQ(b.xmag, 2.0);
  EXPECT_DOUBLE_EQ(b.ymag, 1.0);
  const glm::dmat4 expected = glm::rotate(glm::dmat4(1.0), kPi / 2, Vec3(0, 1, 0)) *
                              glm::translate(glm::dmat4(1.0), Vec3(0, 1, 0));
  for (int col = 0; col < 4; ++col) expectNear(Vec3(b.cameraToWorld[col]), Vec3(expected[col]));
  expectNear(Vec3(b.cameraToWorld * glm::dvec4(0, 0, -1, 0)), {-1, 0, 0});  // looks down world −X

  EXPECT_DOUBLE_EQ(s.cameras[2].aspectRatio, 0.0);
  EXPECT_DOUBLE_EQ(s.cameras[2].yfov, 0.7);
}

TEST(SceneLoader, ReadsMaterials) {
  GltfDoc g;
  g.doc["materials"] = {
      {{"name", "lamp"},
       {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}}},
       {"emissiveFactor", {1.0, 0.5, 0.0}},
       {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}},
      {{"name", "bronze"},
       {"extras", {{"glossy", {{"material", "materials/library/merl/alum-bronze.toml"}, {"fit", "microfacet:E2"}}}}}},
      {{"name", "glow"}, {"emissiveFactor", {0.5, 0.5, 0.5}}}};
  g.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  const int pos = g.addPositions(kQuad), idx = g.addIndices(kQuadIndices);
  const int a = g.addMeshNode("A", {{"attributes", {{"POSITION", pos}}}, {"indices", idx}, {"material", 0}});
  const int b = g.addMeshNode("B", {{"attributes", {{"POSITION", pos}}}, {"indices", idx}, {"material", 1}});
  const int c = g.addMeshNode("C", {{"attributes", {{"POSITION", pos}}}, {"indices", idx}});
  g.setScene({a, b, c});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "materials"));
  ASSERT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(s.materials[0].name, "lamp");
  expectNear(s.materials[0].baseColor, {0.2, 0.4, 0.6});
  expectNear(s.materials[0].emission, {4.0, 2.0, 0.0});
  EXPECT_TRUE(s.materials[0].isEmissive());
  EXPECT_TRUE(s.materials[0].glossyMaterial.empty());
  EXPECT_EQ(s.materials[1].glossyMaterial, "materials/library/merl/alum-bronze.toml");
  EXPECT_EQ(s.materials[1].glossyFit, "microfacet:E2");
  EXPECT_FALSE(s.materials[1].isEmissive());
  expectNear(s.materials[1].baseColor, {1.0, 1.0, 1.0});  // glTF's default baseColorFactor
  expectNear(s.materials[2].emission, {0.5, 0.5, 0.5});   // no strength extension: factor 1
  ASSERT_EQ(s.meshes.size(), 3u);
  EXPECT_EQ(s.meshes[0].material, 0);
  EXPECT_EQ(s.meshes[1].material, 1);
  EXPECT_EQ(s.meshes[2].material, -1);
}

// ---- Skipped and dropped input ----

TEST(SceneLoader, SkipsNonTriangleModesWithOneWarning) {
  GltfDoc g;
  const int pos = g.addPositions(kQuad);
  json lines = {{"attributes", {{"POSITION", pos}}}, {"mode", kLines}};
  json triangles = {{"attributes", {{"POSITION", pos}}}, {"indices", g.addIndices(kQuadIndices)}};
  g.doc["meshes"] = {{{"name", "Mixed"}, {"primitives", {lines, triangles, lines}}}};
  g.doc["nodes"] = {{{"mesh", 0}}};
  g.setScene({0});
  TempDir dir;
  testing::internal::CaptureStderr();
  const SceneDescription s = loadGltf(g.writeExternal(dir, "mixed"));
  flushNotes();  // the command line prints the loader's notes once the input has proved good
  const std::string err = testing::internal::GetCapturedStderr();
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_CONTAINS(s.meshes[0].name, "primitive 1");
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_CONTAINS(err, "mixed.gltf");
  EXPECT_EQ(err.rfind("glossy: ", 0), 0u) << err;

  g.doc["meshes"][0]["primitives"] = {lines};
  testing::internal::CaptureStderr();
  const std::string e = expectInputError([&] { loadGltf(g.writeExternal(dir, "lines")); });
  discardNotes();
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << "a note before the error";
  EXPECT_CONTAINS(e, "lines.gltf");
  EXPECT_CONTAINS(e, "no TRIANGLES");
}

TEST(SceneLoader, DropsZeroAreaTrianglesSilently) {
  GltfDoc g;
  const std::vector<uint32_t> indices = {0, 1, 2, 0, 0, 1, 1, 2, 2, 0, 2, 3};
  g.setScene({g.addMeshNode("Quad", {{"attributes", {{"POSITION", g.addPositions(kQuad)}}}, {"indices", g.addIndices(indices)}})});
  TempDir dir;
  const SceneDescription s = loadGltf(g.writeExternal(dir, "some-degenerate"));
  EXPECT_EQ(s.meshes[0].indices, kQuadIndices);
}

// ---- Errors ----

TEST(SceneLoaderErrors, MissingFile) {
  TempDir dir;
  const std::string e = expectInputError([&] { loadGltf(dir / "absent.gltf"); });
  EXPECT_CONTAINS(e, "absent.gltf");
}

TEST(SceneLoaderErrors, BrokenJson) {
  TempDir dir;
  writeText(dir / "broken.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": [ {");
  EXPECT_CONTAINS(expectInputError([&] { loadGltf(dir / "broken.gltf"); }), "broken.gltf");
  writeText(dir / "garbage.glb", std::string("glTF\x02\0\0\0\xff\xff", 10));
  EXPECT_CONTAINS(expectInputError([&] { loadGltf(dir / "garbage.glb"); }), "garbage.glb");
}

TEST(SceneLoaderErrors, MissingBufferFile) {
  TempDir dir;
  const auto path = quadDoc().writeExternal(dir, "quad");
  std::filesystem::remove(dir / "quad.bin");
  EXPECT_CONTAINS(expectInputError([&] { loadGltf(path); }), "quad.gltf");
}

TEST(SceneLoaderErrors, IndexOutOfRange) {
  GltfDoc g;
  g.setScene({g.addMeshNode(
      "Quad", {{"attributes", {{"POSITION", g.addPositions(kQuad)}}}, {"indices", g.addIndices({0, 1, 7})}})});
  TempDir dir;
  const std::string e = expectInputError([&] { loadGltf(g.writeExternal(dir, "badindex")); });
  EXPECT_CONTAINS(e, "badindex.gltf");
  EXPECT_CONTAINS(e, "node 'QuadNode'");
  EXPECT_CONTAINS(e, "mesh 'Quad'");
  EXPECT_CONTAINS(e, "index 7 is out of range");
}

TEST(SceneLoaderErrors, NonFinitePosition) {
  GltfDoc g;
  std::vector<glm::vec3> p = kQuad;
  p[2].y = std::numeric_limits<float>::quiet_NaN();
  g.setScene({g.addMeshNode("Quad", {{"attributes", {{"POSITION", g.addPositions(p)}}}, {"indices", g.addIndices(kQuadIndices)}})});
  TempDir dir;
  const std::string e = expectInputError([&] { loadGltf(g.writeExternal(dir, "nan")); });
  EXPECT_CONTAINS(e, "nan.gltf");
  EXPECT_CONTAINS(e, "mesh 'Quad'");
  EXPECT_CONTAINS(e, "position 2 is not finite");
}

TEST(SceneLoaderErrors, AllTrianglesDegenerate) {
  GltfDoc g;
  const std::vector<glm::vec3> line = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  g.setScene({g.addMeshNode("Flat", {{"attributes", {{"POSITION", g.addPositions(line)}}}})});
  TempDir dir;
  const std::string e = expectInputError([&] { loadGltf(g.writeExternal(dir, "flat")); });
  EXPECT_CONTAINS(e, "flat.gltf");
  EXPECT_CONTAINS(e, "mesh 'Flat'");
  EXPECT_CONTAINS(e, "zero area");
}

TEST(SceneLoaderErrors, AccessorOfTheWrongType) {
  GltfDoc g;
  const std::vector<float> xy = {0, 0, 1, 0, 1, 1};
  const int pos = g.addAccessor(g.addView(bytesOf(xy)), kFloat, "VEC2", 3);
  g.setScene({g.addMeshNode("Flat", {{"attributes", {{"POSITION", pos}}}})});
  TempDir dir;
  const std::string e = expectInputError([&] { loadGltf(g.writeExternal(dir, "vec2")); });
  EXPECT_CONTAINS(e, "vec2.gltf");
  EXPECT_CONTAINS(e, "POSITION accessor 0 is VEC2 of FLOAT, expected VEC3 of FLOAT");

  g.doc["accessors"][0]["type"] = "VEC3";
  g.doc["accessors"][0]["count"] = 100;  // runs past its buffer view
  EXPECT_CONTAINS(expectInputError([&] { loadGltf(g.writeExternal(dir, "long")); }), "past the end");
}

TEST(SceneLoaderErrors, BadReferencesAndHierarchy) {
  TempDir dir;
  GltfDoc g = quadDoc();
  g.doc["meshes"][0]["primitives"][0]["material"] = 3;
  EXPECT_CONTAINS(expectInputError([&] { loadGltf(g.writeExternal(dir, "mat")); }), "material 3 does not exist");

  GltfDoc cyclic = quadDoc();
  cyclic.doc["nodes"].push_back({{"name", "Loop"}, {"children", {0}}});
  cyclic.doc["nodes"][0]["children"] = {1};
  const std::string e = expectInputError([&] { loadGltf(cyclic.writeExternal(dir, "cycle")); });
  EXPECT_CONTAINS(e, "cycle.gltf");
}

// ---- Embree queries ----

SceneDescription quadScene(bool withNormals) {
  SceneDescription s;
  Mesh m;
  m.name = "quad";
  m.positions = kQuad;
  m.indices = kQuadIndices;
  if (withNormals) m.normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.meshes.push_back(m);
  return s;
}

TEST(EmbreeScene, HitsAQuadAtTheExpectedDistance) {
  const SceneDescription s = quadScene(false);
  const EmbreeScene scene(s);
  Hit hit;
  ASSERT_TRUE(scene.intersect({{0.75, 0.25, 2.0}, {0, 0, -1}}, hit));
  EXPECT_NEAR(hit.t, 2.0, 1e-6);
  EXPECT_EQ(hit.mesh, 0u);
  EXPECT_EQ(hit.triangle, 0u);
  // Triangle 0 is (0,0,0), (1,0,0), (1,1,0): the point is p0 + u·(p1 − p0) + v·(p2 − p0).
  EXPECT_NEAR(hit.u, 0.5, 1e-6);
  EXPECT_NEAR(hit.v, 0.25, 1e-6);
  expectNear(hit.position, {0.75, 0.25, 0.0});
  expectNear(hit.geometricNormal, {0, 0, 1}, 1e-12);
  expectNear(hit.shadingNormal, {0, 0, 1}, 1e-12);

  // From behind the normal is as wound, not turned toward the ray.
  ASSERT_TRUE(scene.intersect({{0.25, 0.75, -3.0}, {0, 0, 1}}, hit));
  EXPECT_EQ(hit.triangle, 1u);
  EXPECT_NEAR(hit.t, 3.0, 1e-6);
  expectNear(hit.geometricNormal, {0, 0, 1}, 1e-12);

  EXPECT_FALSE(scene.intersect({{2.0, 0.5, 1.0}, {0, 0, -1}}, hit));
  EXPECT_FALSE(scene.intersect({{0.5, 0.5, 1.0}, {0, 0, 1}}, hit));
}

TEST(EmbreeScene, InterpolatesShadingNormals) {
  const SceneDescription s = quadScene(true);
  const EmbreeScene scene(s);
  Hit hit;
  ASSERT_TRUE(scene.intersect({{0.75, 0.25, 2.0}, {0, 0, -1}}, hit));
  const Vec3 blend = (1.0 - hit.u - hit.v) * Vec3(0, 0, 1) + hit.u * Vec3(1, 0, 0) + hit.v * Vec3(0, 1, 0);
  expectNear(hit.shadingNormal, glm::normalize(blend));
  expectNear(hit.geometricNormal, {0, 0, 1}, 1e-12);
}

TEST(EmbreeScene, RespectsTnearAndTfar) {
  SceneDescription s = quadScene(false);
  Mesh lower = s.meshes[0];
  for (glm::vec3& p : lower.positions) p.z = -1.0f;
  s.meshes.push_back(lower);
  const EmbreeScene scene(s);
  Hit hit;
  EXPECT_FALSE(scene.intersect({{0.5, 0.4, 2.0}, {0, 0, -1}, 0.0, 1.5}, hit));
  ASSERT_TRUE(scene.intersect({{0.5, 0.4, 2.0}, {0, 0, -1}, 2.5, 10.0}, hit));
  EXPECT_EQ(hit.mesh, 1u);
  EXPECT_NEAR(hit.t, 3.0, 1e-6);
  EXPECT_FALSE(scene.intersect({{0.5, 0.4, 2.0}, {0, 0, -1}, 3.5, 10.0}, hit));

  EXPECT_TRUE(scene.occluded({{0.5, 0.4, 2.0}, {0, 0, -1}}));
  EXPECT_TRUE(scene.occluded({{0.5, 0.4, 2.0}, {0, 0, -1}, 2.5, 3.5}));
  EXPECT_FALSE(scene.occluded({{0.5, 0.4, 2.0}, {0, 0, -1}, 0.0, 1.9}));
  EXPECT_FALSE(scene.occluded({{0.5, 0.4, 2.0}, {0, 0, -1}, 3.5, 10.0}));
  EXPECT_FALSE(scene.occluded({{0.5, 0.4, 2.0}, {0, 0, 1}}));
}

TEST(EmbreeScene, BoundingSphereEnclosesTheGeometry) {
  const SceneDescription s = quadScene(false);
  const EmbreeScene scene(s);
  expectNear(scene.boundsCenter(), {0.5, 0.5, 0.0});
  EXPECT_NEAR(scene.boundsRadius(), std::sqrt(0.5), 1e-6);
}

TEST(EmbreeScene, RejectsInconsistentMeshes) {
  SceneDescription s = quadScene(false);
  s.meshes[0].indices.back() = 4;
  EXPECT_THROW(EmbreeScene{s}, std::runtime_error);
}

// ---- The committed scenes ----

// A ray through the centre of each camera's image must land on the object.
void expectCamerasSeeTheObject(const SceneDescription& s) {
  const EmbreeScene scene(s);
  ASSERT_FALSE(s.cameras.empty());
  for (const Camera& c : s.cameras) {
    SCOPED_TRACE(c.name);
    const Ray ray{Vec3(c.cameraToWorld[3]), glm::normalize(Vec3(c.cameraToWorld * glm::dvec4(0, 0, -1, 0)))};
    Hit hit;
    ASSERT_TRUE(scene.intersect(ray, hit));
    const int material = s.meshes[hit.mesh].material;
    ASSERT_GE(material, 0);
    EXPECT_EQ(s.materials[size_t(material)].name, "object");
    EXPECT_LT(glm::dot(hit.shadingNormal, ray.dir), 0.0);  // the outside faces the camera
  }
}

TEST(CommittedScenes, Sphere) {
  const auto path = sourceDir() / "scenes" / "sphere.gltf";
  EXPECT_LT(std::filesystem::file_size(sourceDir() / "scenes" / "sphere.bin"), 2u << 20);
  const SceneDescription s = loadGltf(path);
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].glossyMaterial, "materials/library/merl/alum-bronze.toml");
  EXPECT_EQ(s.materials[0].glossyFit, "microfacet:E2");
  for (const glm::vec3& p : s.meshes[0].positions) EXPECT_NEAR(glm::length(p), 1.0f, 1e-6f);
  ASSERT_EQ(s.cameras.size(), 2u);
  EXPECT_EQ(s.cameras[0].type, Camera::Type::Perspective);
  EXPECT_NEAR(s.cameras[0].yfov, 35.0 * kPi / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.cameras[0].aspectRatio, 1.0);
  expectNear(Vec3(s.cameras[0].cameraToWorld[3]), {0, 1, 4});
  EXPECT_EQ(s.cameras[1].name, "ortho");
  EXPECT_EQ(s.cameras[1].type, Camera::Type::Orthographic);
  EXPECT_DOUBLE_EQ(s.cameras[1].xmag, 1.05);
  expectNear(Vec3(s.cameras[1].cameraToWorld[3]), {0, 0, 5});
  expectCamerasSeeTheObject(s);

  const EmbreeScene scene(s);
  Hit hit;
  ASSERT_TRUE(scene.intersect({{0, 0, 5}, {0, 0, -1}}, hit));
  EXPECT_NEAR(hit.t, 4.0, 1e-5);
  expectNear(hit.shadingNormal, {0, 0, 1}, 1e-5);
  EXPECT_NEAR(scene.boundsRadius(), 1.0, 1e-5);
}

TEST(CommittedScenes, Preview) {
  EXPECT_LT(std::filesystem::file_size(sourceDir() / "scenes" / "preview.bin"), 2u << 20);
  const SceneDescription s = loadGltf(sourceDir() / "scenes" / "preview.gltf");
  ASSERT_EQ(s.cameras.size(), 1u);
  EXPECT_DOUBLE_EQ(s.cameras[0].aspectRatio, 1.0);
  bool backdrop = false;
  for (const SceneMaterial& m : s.materials)
    if (m.name == "backdrop") {
      backdrop = true;
      expectNear(m.baseColor, {0.5, 0.5, 0.5});
      EXPECT_TRUE(m.glossyMaterial.empty());
    } else {
      EXPECT_EQ(m.glossyMaterial, "materials/library/merl/alum-bronze.toml");
    }
  EXPECT_TRUE(backdrop);
  expectCamerasSeeTheObject(s);
}

}  // namespace

}  // namespace glossy::test
