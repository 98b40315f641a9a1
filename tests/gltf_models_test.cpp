// Small but varied glTF and GLB files, in the spirit of the Khronos sample collection, written here and
// rendered through the command line at 32², 4 spp: each must exit 0 with finite pixels and the object in
// view. scripts/make-gltf-contact-sheet does the same for real models from a folder, or for these (it sets
// GLOSSY_KEEP_GLTF_MODELS to a folder, into which the test then copies the files it wrote).
#include "renderer/image/exr_image.h"
#include "tests/support/gltf_doc.h"
#include "tests/support/test_support.h"

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstdlib>
#include <functional>

namespace glossy::test {

namespace {

using nlohmann::json;

struct Model {
  std::string name;
  std::function<std::filesystem::path(const TempDir&)> write;
};

json withMaterial(json prim, int material) {
  prim["material"] = material;
  return prim;
}

GltfDoc single(json (*make)(GltfDoc&)) {
  GltfDoc g;
  g.setScene({g.addMeshNode("Object", make(g))});
  return g;
}

std::vector<Model> models() {
  std::vector<Model> m;
  const auto add = [&](std::string name, std::function<std::filesystem::path(const TempDir&, const std::string&)> w) {
    m.push_back({name, [name, w](const TempDir& d) { return w(d, name); }});
  };
  add("normals-u32", [](const TempDir& d, const std::string& n) {
    return single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 1, 1}, true, kUnsignedInt); }).writeExternal(d, n);
  });
  add("no-normals-u16", [](const TempDir& d, const std::string& n) {
    return single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 2, 1}, false, kUnsignedShort); }).writeExternal(d, n);
  });
  add("u8-indices", [](const TempDir& d, const std::string& n) {
    return single([](GltfDoc& g) { return boxPrimitive(g, {1, 1, 1}, {3, 1, 1}, true, kUnsignedByte); }).writeExternal(d, n);
  });
  add("unindexed-soup", [](const TempDir& d, const std::string& n) {
    return single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 1, 1}, false, 0); }).writeExternal(d, n);
  });
  add("embedded-base64", [](const TempDir& d, const std::string& n) {
    return single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 1, 1}); }).writeEmbedded(d, n);
  });
  add("glb", [](const TempDir& d, const std::string& n) {
    return single([](GltfDoc& g) { return boxPrimitive(g, {0, -1, 0}, {2, 1, 2}); }).writeGlb(d, n);
  });
  add("hierarchy-trs-and-matrix", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    const glm::dquat q = glm::angleAxis(0.7, glm::normalize(Vec3(1, 2, 0.5)));
    const int child = g.addMeshNode("Child", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}),
                                    {{"matrix", {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 2, 0, 0, 1}}});
    const int leaf = g.addMeshNode("Leaf", boxPrimitive(g, {0, 0, 0}, {0.5, 0.5, 0.5}),
                                   {{"translation", {0, 2, 0}}, {"rotation", {q.x, q.y, q.z, q.w}}, {"scale", {1, 3, 1}}});
    const int root = g.push("nodes", {{"name", "Root"}, {"scale", {2, 0.5, 1}}, {"rotation", {0, 0.3826834, 0, 0.9238795}},
                                      {"translation", {10, 0, -5}}, {"children", {child, leaf}}});
    g.setScene({root});
    return g.writeExternal(d, n);
  });
  add("mirrored-node", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    g.setScene({g.addMeshNode("Mirror", boxPrimitive(g, {1, 0, 0}, {1, 1, 1}), {{"scale", {-1, 1, 1}}})});
    return g.writeExternal(d, n);
  });
  add("second-of-two-scenes", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    const int far = g.addMeshNode("Far", boxPrimitive(g, {100, 0, 0}, {1, 1, 1}));
    const int near = g.addMeshNode("Near", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}));
    g.doc["scenes"] = json::array({{{"nodes", {far}}}, {{"nodes", {near}}}});
    g.doc["scene"] = 1;
    return g.writeExternal(d, n);
  });
  add("no-scenes-key", [](const TempDir& d, const std::string& n) {
    GltfDoc g = single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 1, 1}); });
    g.doc.erase("scenes");
    g.doc.erase("scene");
    return g.writeExternal(d, n);
  });
  add("multiple-primitives", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    g.doc["materials"] = {{{"name", "red"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1}}}}},
                          {{"name", "blue"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.1, 0.1, 0.8, 1}}}}}};
    const int mesh = g.push("meshes", {{"name", "Pair"},
                                       {"primitives", {withMaterial(boxPrimitive(g, {-1, 0, 0}, {1, 1, 1}), 0),
                                                       withMaterial(boxPrimitive(g, {1, 0, 0}, {1, 1, 1}, false), 1)}}});
    g.setScene({g.push("nodes", {{"mesh", mesh}})});
    return g.writeExternal(d, n);
  });
  add("shared-mesh-instances", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    const int mesh = g.push("meshes", {{"primitives", {boxPrimitive(g, {0, 0, 0}, {1, 1, 1})}}});
    std::vector<int> roots;
    for (int i = 0; i < 4; ++i) roots.push_back(g.push("nodes", {{"mesh", mesh}, {"translation", {1.5 * i, 0, 0}}}));
    g.setScene(roots);
    return g.writeExternal(d, n);
  });
  add("interleaved-strided", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    std::vector<float> data;  // position, normal per vertex: a single triangle pair facing +Z
    for (auto [x, y] : {std::pair{-1.f, -1.f}, {1.f, -1.f}, {1.f, 1.f}, {-1.f, 1.f}}) data.insert(data.end(), {x, y, 0, 0, 0, 1});
    const int view = g.addView(bytesOf(data), 24);
    const int pos = g.addAccessor(view, kFloat, "VEC3", 4, 0);
    const int nrm = g.addAccessor(view, kFloat, "VEC3", 4, 12);
    g.setScene({g.addMeshNode("Card", {{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}},
                                       {"indices", g.addIndices({0, 1, 2, 0, 2, 3}, kUnsignedShort)}})});
    return g.writeExternal(d, n);
  });
  add("perspective-camera", [](const TempDir& d, const std::string& n) {
    GltfDoc g = single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 1, 1}); });
    g.doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    g.doc["scenes"][0]["nodes"].push_back(g.push("nodes", {{"camera", 0}, {"translation", {0, 0, 3}}}));
    return g.writeExternal(d, n);
  });
  add("orthographic-camera-in-rig", [](const TempDir& d, const std::string& n) {
    GltfDoc g = single([](GltfDoc& g) { return boxPrimitive(g, {0, 0, 0}, {1, 1, 1}); });
    g.doc["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 1.5}, {"ymag", 1.5}, {"znear", 0.1}, {"zfar", 100}}}}};
    const int cam = g.push("nodes", {{"camera", 0}, {"translation", {0, 0, 5}}});
    const int rig = g.push("nodes", {{"rotation", {0, 0.7071068, 0, 0.7071068}}, {"children", {cam}}});
    g.doc["scenes"][0]["nodes"].push_back(rig);
    return g.writeExternal(d, n);
  });
  add("emissive-strength-required", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    g.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    g.doc["extensionsRequired"] = {"KHR_materials_emissive_strength"};
    g.doc["materials"] = {{{"name", "lamp"}, {"emissiveFactor", {1, 0.9, 0.8}},
                           {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 3.0}}}}}}};
    g.setScene({g.addMeshNode("Lamp", withMaterial(boxPrimitive(g, {0, 2, 0}, {1, 0.1, 1}), 0)),
                g.addMeshNode("Floor", boxPrimitive(g, {0, 0, 0}, {3, 0.2, 3}))});
    return g.writeExternal(d, n);
  });
  add("points-beside-triangles", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    const int pts = g.addPositions({{0, 3, 0}, {1, 3, 0}});
    const int mesh = g.push("meshes", {{"primitives", {{{"attributes", {{"POSITION", pts}}}, {"mode", 0}},
                                                       boxPrimitive(g, {0, 0, 0}, {1, 1, 1})}}});
    g.setScene({g.push("nodes", {{"mesh", mesh}})});
    return g.writeExternal(d, n);
  });
  add("hidden-by-scale-zero", [](const TempDir& d, const std::string& n) {
    GltfDoc g;
    g.setScene({g.addMeshNode("Shown", boxPrimitive(g, {0, 0, 0}, {1, 1, 1})),
                g.addMeshNode("Hidden", boxPrimitive(g, {0, 0, 0}, {9, 9, 9}), {{"scale", {0, 0, 0}}})});
    return g.writeGlb(d, n);
  });
  add("textured-ignored", [](const TempDir& d, const std::string& n) {
    GltfDoc g = single([](GltfDoc& g) { return withMaterial(boxPrimitive(g, {0, 0, 0}, {1, 1, 1}), 0); });
    g.doc["extensionsUsed"] = {"KHR_texture_transform"};
    g.doc["extensionsRequired"] = {"KHR_texture_transform"};
    g.doc["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgo="}}};
    g.doc["samplers"] = {{{"magFilter", 9729}}};
    g.doc["textures"] = {{{"source", 0}, {"sampler", 0}}};
    g.doc["materials"] = {{{"name", "wood"},
                           {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"scale", {2, 2}}}}}}}}}},
                           {"normalTexture", {{"index", 0}}}}};
    return g.writeExternal(d, n);
  });
  add("glossy-binding", [](const TempDir& d, const std::string& n) {
    GltfDoc g = single([](GltfDoc& g) { return withMaterial(boxPrimitive(g, {0, 0, 0}, {1, 1, 1}), 0); });
    g.doc["materials"] = {{{"name", "metal"},
                           {"extras", {{"glossy", {{"material", (materialsDir() / "chrome.toml").string()}, {"fit", "cook-torrance:E2"}}}}}}};
    return g.writeExternal(d, n);
  });
  return m;
}

}  // namespace

TEST(GltfModels, VariedFilesRenderWithTheObjectInView) {
  TempDir dir;
  const std::vector<Model> all = models();
  ASSERT_GE(all.size(), 15u);
  for (const Model& model : all) {
    SCOPED_TRACE(model.name);
    const auto path = model.write(dir);
    const auto out = dir / (model.name + ".exr");
    // Emitters only (--max-depth 1): under a constant sky of 1 the object is black wherever it is seen, whatever
    // its material. (Lit, a white diffuse object under a constant sky is exactly as bright as the sky.)
    const RunResult r = runGlossy({"render", "--scene", path.string(), "--width", "32", "--height", "32", "--spp", "4",
                                   "--env-constant", "1", "--max-depth", "1", "-o", out.string()});
    ASSERT_EQ(r.status, 0) << r.err;
    const RgbImage image = readRgbImage(out);
    int object = 0;
    for (size_t i = 0; i < image.pixels.size(); i += 3) {
      ASSERT_TRUE(std::isfinite(image.pixels[i]) && std::isfinite(image.pixels[i + 1]) && std::isfinite(image.pixels[i + 2]));
      // The object's pixels are darker than the sky's (partly covered ones by their share).
      if (std::abs(image.pixels[i] - 1.0f) + std::abs(image.pixels[i + 2] - 1.0f) > 0.02f) ++object;
    }
    EXPECT_GT(object, 32 * 32 / 20) << "the object covers " << object << " pixels";
  }
  if (const char* keep = std::getenv("GLOSSY_KEEP_GLTF_MODELS"); keep && *keep) {
    std::filesystem::create_directories(keep);
    for (const auto& entry : std::filesystem::directory_iterator(dir.path()))
      if (entry.path().extension() != ".exr")
        std::filesystem::copy(entry.path(), std::filesystem::path(keep) / entry.path().filename(),
                              std::filesystem::copy_options::overwrite_existing);
  }
}

TEST(GltfModels, SparseAccessorsAreRefusedCleanly) {
  GltfDoc g;
  g.setScene({g.addMeshNode("Sparse", boxPrimitive(g, {0, 0, 0}, {1, 1, 1}))});
  const int position = g.doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"];
  const int indices = g.addView(bytesOf(std::vector<uint16_t>{0, 1}));
  const int values = g.addView(bytesOf(std::vector<glm::vec3>{{0, 0, 2}, {0, 0, 2}}));
  g.doc["accessors"][position]["sparse"] = {{"count", 2},
                                            {"indices", {{"bufferView", indices}, {"componentType", kUnsignedShort}}},
                                            {"values", {{"bufferView", values}}}};
  TempDir dir;
  expectOneLineError(runGlossy({"render", "--scene", g.writeExternal(dir, "sparse").string(), "--width", "8", "--height", "8",
                                "--spp", "1", "-o", (dir / "x.exr").string()}),
                     "sparse");
}

}  // namespace glossy::test
