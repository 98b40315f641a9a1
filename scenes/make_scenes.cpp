// Writes the committed example scenes from procedural meshes, so they stay reproducible and reviewable as
// code: sphere.gltf (a smooth unit sphere, a perspective and an orthographic camera) and preview.gltf (a
// shader-ball-like object on a curved backdrop). Each gets one external .bin. Usage: make_scenes OUT_DIR
#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

namespace {

constexpr double kPi = std::numbers::pi;

double radians(double degrees) { return degrees * kPi / 180.0; }

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<uint32_t> indices;

  uint32_t addVertex(const glm::dvec3& p, const glm::dvec3& n) {
    positions.emplace_back(p);
    normals.emplace_back(glm::normalize(n));
    return uint32_t(positions.size() - 1);
  }
  // Winds each triangle to face its vertex normals, so the generators need not track orientation, and
  // leaves out the zero-area triangles that collapsed rings (poles, axis points) produce.
  void addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    const glm::dvec3 p0(positions[a]), p1(positions[b]), p2(positions[c]);
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    if (glm::length(n) < 1e-12) return;
    const glm::dvec3 shading = glm::dvec3(normals[a]) + glm::dvec3(normals[b]) + glm::dvec3(normals[c]);
    if (glm::dot(n, shading) < 0.0) std::swap(b, c);
    indices.insert(indices.end(), {a, b, c});
  }
  // A grid of rows × columns vertices, row-major from `first`, as quads of two triangles.
  void addGrid(uint32_t first, int rows, int columns) {
    for (int i = 0; i + 1 < rows; ++i)
      for (int j = 0; j + 1 < columns; ++j) {
        const uint32_t a = first + uint32_t(i * columns + j), b = a + 1, c = a + uint32_t(columns) + 1,
                       d = a + uint32_t(columns);
        addTriangle(a, b, c);
        addTriangle(a, c, d);
      }
  }
};

// A point of a 2D profile curve with its outward unit normal.
struct ProfilePoint {
  glm::dvec2 p;
  glm::dvec2 n;
};
using Profile = std::vector<ProfilePoint>;

void appendLine(Profile& profile, glm::dvec2 from, glm::dvec2 to, glm::dvec2 normal) {
  profile.push_back({from, normal});
  profile.push_back({to, normal});
}

// An arc of a circle from angle a0 to a1; `convex` says whether the outward normal points away from the
// centre (a bulge) or toward it (a fillet).
void appendArc(Profile& profile, glm::dvec2 centre, double radius, double a0, double a1, int steps, bool convex) {
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + (a1 - a0) * k / steps;
    const glm::dvec2 dir(std::cos(a), std::sin(a));
    profile.push_back({centre + radius * dir, convex ? dir : -dir});
  }
}

// A surface of revolution about +Y of a profile in (radius, height); the seam's vertices are duplicated.
MeshData lathe(const Profile& profile, int segments) {
  MeshData mesh;
  for (const ProfilePoint& q : profile)
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2.0 * kPi * j / segments;
      const glm::dvec3 around(std::cos(phi), 0.0, -std::sin(phi));
      mesh.addVertex(around * q.p.x + glm::dvec3(0.0, q.p.y, 0.0), around * q.n.x + glm::dvec3(0.0, q.n.y, 0.0));
    }
  mesh.addGrid(0, int(profile.size()), segments + 1);
  return mesh;
}

// A profile in (z, height) swept along X from x0 to x1.
MeshData extrude(const Profile& profile, double x0, double x1) {
  MeshData mesh;
  for (const ProfilePoint& q : profile) {
    mesh.addVertex({x0, q.p.y, q.p.x}, {0.0, q.n.y, q.n.x});
    mesh.addVertex({x1, q.p.y, q.p.x}, {0.0, q.n.y, q.n.x});
  }
  mesh.addGrid(0, int(profile.size()), 2);
  return mesh;
}

MeshData uvSphere(double radius, int segments, int rings) {
  Profile half;
  appendArc(half, {0.0, 0.0}, radius, -kPi / 2, kPi / 2, rings, true);
  return lathe(half, segments);
}

MeshData torus(double major, double minor, int segments, int sides) {
  Profile circle;
  appendArc(circle, {major, 0.0}, minor, 0.0, 2.0 * kPi, sides, true);
  return lathe(circle, segments);
}

// A round base with a softened edge that flows through a concave fillet into a slim neck; the neck's top
// ends inside the ball that sits on it.
MeshData pedestal(int segments) {
  Profile bottom;
  appendLine(bottom, {0.0, 0.0}, {0.62, 0.0}, {0.0, -1.0});
  Profile body;
  appendLine(body, {0.62, 0.0}, {0.62, 0.08}, {1.0, 0.0});
  appendArc(body, {0.56, 0.08}, 0.06, 0.0, kPi / 2, 8, true);
  appendLine(body, {0.56, 0.14}, {0.42, 0.14}, {0.0, 1.0});
  appendArc(body, {0.42, 0.34}, 0.2, -kPi / 2, -kPi, 16, false);
  appendLine(body, {0.22, 0.34}, {0.22, 0.62}, {1.0, 0.0});

  MeshData mesh = lathe(bottom, segments);
  const MeshData rest = lathe(body, segments);
  const uint32_t offset = uint32_t(mesh.positions.size());
  mesh.positions.insert(mesh.positions.end(), rest.positions.begin(), rest.positions.end());
  mesh.normals.insert(mesh.normals.end(), rest.normals.begin(), rest.normals.end());
  for (uint32_t i : rest.indices) mesh.indices.push_back(i + offset);
  return mesh;
}

// A photographer's sweep: the floor bends up through a quarter cylinder into the back wall, so the
// object has no horizon line behind it.
MeshData backdrop() {
  const double bendRadius = 2.5, bendStartZ = -1.5;
  Profile sweep;
  appendLine(sweep, {8.0, 0.0}, {bendStartZ, 0.0}, {0.0, 1.0});
  appendArc(sweep, {bendStartZ, bendRadius}, bendRadius, -kPi / 2, -kPi, 48, false);
  appendLine(sweep, {bendStartZ - bendRadius, bendRadius}, {bendStartZ - bendRadius, 8.0}, {1.0, 0.0});
  return extrude(sweep, -8.0, 8.0);
}

// Builds a tinygltf model whose meshes all live in one buffer.
class GltfBuilder {
 public:
  explicit GltfBuilder(const std::string& binName) {
    model_.asset.version = "2.0";
    model_.asset.generator = "glossy scenes/make_scenes.cpp";
    model_.buffers.emplace_back();
    model_.buffers[0].uri = binName;
    model_.scenes.emplace_back();
    model_.defaultScene = 0;
  }

  int addMaterial(const std::string& name, glm::dvec3 baseColor, double metallic, double roughness,
                  const std::string& glossyMaterial = "", const std::string& glossyFit = "") {
    tinygltf::Material m;
    m.name = name;
    m.pbrMetallicRoughness.baseColorFactor = {baseColor.r, baseColor.g, baseColor.b, 1.0};
    m.pbrMetallicRoughness.metallicFactor = metallic;
    m.pbrMetallicRoughness.roughnessFactor = roughness;
    if (!glossyMaterial.empty()) {
      tinygltf::Value::Object binding{{"material", tinygltf::Value(glossyMaterial)},
                                      {"fit", tinygltf::Value(glossyFit)}};
      m.extras = tinygltf::Value(tinygltf::Value::Object{{"glossy", tinygltf::Value(binding)}});
    }
    model_.materials.push_back(m);
    return int(model_.materials.size() - 1);
  }

  int addMesh(const std::string& name, const MeshData& data, int material) {
    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = material;
    prim.attributes["POSITION"] = addAccessor(data.positions, true);
    prim.attributes["NORMAL"] = addAccessor(data.normals, false);
    prim.indices = addIndices(data.indices);
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(prim);
    model_.meshes.push_back(mesh);
    return int(model_.meshes.size() - 1);
  }

  int addPerspectiveCamera(const std::string& name, double yfovDegrees, double aspect) {
    tinygltf::Camera c;
    c.name = name;
    c.type = "perspective";
    c.perspective.yfov = radians(yfovDegrees);
    c.perspective.aspectRatio = aspect;
    c.perspective.znear = 0.05;
    c.perspective.zfar = 100.0;
    model_.cameras.push_back(c);
    return int(model_.cameras.size() - 1);
  }

  int addOrthographicCamera(const std::string& name, double xmag, double ymag) {
    tinygltf::Camera c;
    c.name = name;
    c.type = "orthographic";
    c.orthographic.xmag = xmag;
    c.orthographic.ymag = ymag;
    c.orthographic.znear = 0.05;
    c.orthographic.zfar = 100.0;
    model_.cameras.push_back(c);
    return int(model_.cameras.size() - 1);
  }

  // The reference is valid until the next addNode.
  tinygltf::Node& addNode(const std::string& name) {
    model_.nodes.emplace_back();
    model_.nodes.back().name = name;
    model_.scenes[0].nodes.push_back(int(model_.nodes.size() - 1));
    return model_.nodes.back();
  }

  bool write(const std::filesystem::path& path) {
    tinygltf::TinyGLTF writer;
    return writer.WriteGltfSceneToFile(&model_, path.string(), false, false, true, false);
  }

 private:
  int addView(const void* bytes, size_t size, int target) {
    std::vector<unsigned char>& data = model_.buffers[0].data;
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = data.size();
    view.byteLength = size;
    view.target = target;
    data.resize(data.size() + size);
    std::memcpy(data.data() + view.byteOffset, bytes, size);
    model_.bufferViews.push_back(view);
    return int(model_.bufferViews.size() - 1);
  }

  int addAccessor(const std::vector<glm::vec3>& values, bool withBounds) {
    tinygltf::Accessor a;
    a.bufferView = addView(values.data(), values.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.type = TINYGLTF_TYPE_VEC3;
    a.count = values.size();
    if (withBounds) {  // glTF requires min and max on POSITION
      glm::vec3 lo(values[0]), hi(values[0]);
      for (const glm::vec3& v : values) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
      }
      a.minValues = {lo.x, lo.y, lo.z};
      a.maxValues = {hi.x, hi.y, hi.z};
    }
    model_.accessors.push_back(a);
    return int(model_.accessors.size() - 1);
  }

  int addIndices(const std::vector<uint32_t>& indices) {
    tinygltf::Accessor a;
    a.bufferView =
        addView(indices.data(), indices.size() * sizeof(uint32_t), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
    a.type = TINYGLTF_TYPE_SCALAR;
    a.count = indices.size();
    model_.accessors.push_back(a);
    return int(model_.accessors.size() - 1);
  }

  tinygltf::Model model_;
};

void place(tinygltf::Node& node, glm::dvec3 translation, glm::dquat rotation = glm::dquat(1.0, 0.0, 0.0, 0.0)) {
  node.translation = {translation.x, translation.y, translation.z};
  if (rotation != glm::dquat(1.0, 0.0, 0.0, 0.0)) node.rotation = {rotation.x, rotation.y, rotation.z, rotation.w};
}

// A camera node at `eye` looking at `target`, +Y up (glTF cameras look down their −Z).
void aim(tinygltf::Node& node, glm::dvec3 eye, glm::dvec3 target) {
  const glm::dmat4 cameraToWorld = glm::inverse(glm::lookAt(eye, target, glm::dvec3(0.0, 1.0, 0.0)));
  place(node, eye, glm::quat_cast(glm::dmat3(cameraToWorld)));
}

const char* const kGlossyMaterial = "materials/library/merl/alum-bronze.toml";
const char* const kGlossyFit = "microfacet:E2";

bool writeSphere(const std::filesystem::path& dir) {
  GltfBuilder b("sphere.bin");
  const int object = b.addMaterial("object", {0.8, 0.8, 0.8}, 0.0, 0.5, kGlossyMaterial, kGlossyFit);
  b.addNode("Sphere").mesh = b.addMesh("Sphere", uvSphere(1.0, 128, 64), object);
  tinygltf::Node& camera = b.addNode("Camera");
  camera.camera = b.addPerspectiveCamera("Camera", 35.0, 1.0);
  aim(camera, {0.0, 1.0, 4.0}, {0.0, 0.0, 0.0});
  tinygltf::Node& ortho = b.addNode("ortho");
  ortho.camera = b.addOrthographicCamera("ortho", 1.05, 1.05);
  place(ortho, {0.0, 0.0, 5.0});
  return b.write(dir / "sphere.gltf");
}

bool writePreview(const std::filesystem::path& dir) {
  GltfBuilder b("preview.bin");
  const int object = b.addMaterial("object", {0.8, 0.8, 0.8}, 0.0, 0.5, kGlossyMaterial, kGlossyFit);
  const int grey = b.addMaterial("backdrop", {0.5, 0.5, 0.5}, 0.0, 1.0);

  const glm::dvec3 ballCentre(0.0, 1.3, 0.0);
  tinygltf::Node& ball = b.addNode("Ball");
  ball.mesh = b.addMesh("Ball", uvSphere(0.8, 128, 64), object);
  place(ball, ballCentre);
  b.addNode("Pedestal").mesh = b.addMesh("Pedestal", pedestal(128), object);
  // The ring sinks slightly into the ball, so the two meet in a concave crease, and is tilted so its
  // inside (a saddle) faces the camera.
  tinygltf::Node& ring = b.addNode("Ring");
  ring.mesh = b.addMesh("Ring", torus(0.86, 0.09, 128, 32), object);
  place(ring, ballCentre,
        glm::angleAxis(radians(-12.0), glm::dvec3(0.0, 0.0, 1.0)) *
            glm::angleAxis(radians(24.0), glm::dvec3(1.0, 0.0, 0.0)));
  b.addNode("Backdrop").mesh = b.addMesh("Backdrop", backdrop(), grey);

  tinygltf::Node& camera = b.addNode("Camera");
  camera.camera = b.addPerspectiveCamera("Camera", 30.0, 1.0);
  aim(camera, {0.0, 1.8, 6.3}, {0.0, 1.0, 0.0});
  return b.write(dir / "preview.gltf");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: make_scenes OUT_DIR\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  if (!writeSphere(dir) || !writePreview(dir)) {
    std::cerr << "make_scenes: cannot write the scenes into " << dir.string() << "\n";
    return 1;
  }
  return 0;
}
