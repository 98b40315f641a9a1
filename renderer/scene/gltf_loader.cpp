// glTF 2.0 → SceneDescription: the default scene's node tree flattened into world-space triangle meshes,
// with its materials and cameras. Everything read from the file is checked before use, so malformed input
// ends in one InputError line instead of a crash or garbage geometry.
#include "renderer/scene/scene.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "renderer/util/digest.h"
#include "renderer/util/notes.h"
#include "materials/core/text.h"
#include "renderer/scene/gltf_preflight.h"

#include <tiny_gltf.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <span>
#include <utility>

namespace glossy {

namespace {

// The brightest colour × intensity a punctual light may have: the bound --env-constant's radiance has
// (renderer/app/scene_options.cpp), so that it times the brightest accepted BRDF peak stays finite in float.
constexpr double kMaxLightIntensity = 1e12;

std::string label(const char* kind, const std::string& name, int index) {
  return name.empty() ? std::string(kind) + " " + std::to_string(index) : std::string(kind) + " '" + name + "'";
}

bool allFinite(std::span<const double> values) {
  return std::all_of(values.begin(), values.end(), [](double x) { return std::isfinite(x); });
}

// glTF's names of an accessor's component type and type, for messages.
const char* componentTypeName(int componentType) {
  static const std::map<int, const char*> names = {
      {TINYGLTF_COMPONENT_TYPE_BYTE, "BYTE"},   {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, "UNSIGNED_BYTE"},
      {TINYGLTF_COMPONENT_TYPE_SHORT, "SHORT"}, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "UNSIGNED_SHORT"},
      {TINYGLTF_COMPONENT_TYPE_INT, "INT"},     {TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, "UNSIGNED_INT"},
      {TINYGLTF_COMPONENT_TYPE_FLOAT, "FLOAT"}, {TINYGLTF_COMPONENT_TYPE_DOUBLE, "DOUBLE"}};
  const auto name = names.find(componentType);
  return name == names.end() ? "an unknown component type" : name->second;
}
const char* typeName(int type) {
  static const std::map<int, const char*> names = {
      {TINYGLTF_TYPE_SCALAR, "SCALAR"}, {TINYGLTF_TYPE_VEC2, "VEC2"}, {TINYGLTF_TYPE_VEC3, "VEC3"}, {TINYGLTF_TYPE_VEC4, "VEC4"},
      {TINYGLTF_TYPE_MAT2, "MAT2"},     {TINYGLTF_TYPE_MAT3, "MAT3"}, {TINYGLTF_TYPE_MAT4, "MAT4"}};
  const auto name = names.find(type);
  return name == names.end() ? "an unknown type" : name->second;
}

// The renderer uses no textures: skipping their decoding saves time and keeps image formats stb cannot
// read from failing an otherwise good scene.
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
                 void*) {
  return true;
}

// An accessor's elements after its whole extent has been checked against its buffer view and buffer, so
// reading them needs no further checks.
struct AccessorData {
  const unsigned char* first = nullptr;  // null: the accessor has no buffer view, all elements are zero
  size_t stride = 0;
  size_t count = 0;
  int componentType = 0;

  // Element i as a T (zero without a buffer view), read unaligned.
  template <class T>
  T get(size_t i) const {
    T x{};
    if (first) std::memcpy(&x, first + i * stride, sizeof x);
    return x;
  }
  glm::vec3 vec3(size_t i) const { return get<glm::vec3>(i); }
  uint32_t index(size_t i) const {
    if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return get<uint8_t>(i);
    if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) return get<uint16_t>(i);
    return get<uint32_t>(i);
  }
};

class GltfReader {
 public:
  GltfReader(const std::filesystem::path& path, const tinygltf::Model& model)
      : path_(path), model_(model), visited_(model.nodes.size(), 0) {}

  SceneDescription read() {
    scene_.source = path_;
    if (model_.defaultScene < -1 || (model_.defaultScene >= 0 && size_t(model_.defaultScene) >= model_.scenes.size()))
      fail("scene " + std::to_string(model_.defaultScene) + " does not exist (the file has " +
           std::to_string(model_.scenes.size()) + " scenes)");
    readMaterials();
    for (int root : rootNodes()) walk(root);
    if (scene_.meshes.empty())
      fail(skippedPrimitives_ > 0 ? "the scene has no TRIANGLES primitives (only points, lines or strips)"
           : !singularNodes_.empty() ? "the scene has no triangle meshes (those of " + singularNodes_ +
                                           " are under a singular transform)"
                                     : "the scene has no triangle meshes");
    if (skippedPrimitives_ > 0)
      note(printableLine(path_.string() + ": warning: skipped " + std::to_string(skippedPrimitives_) +
                   " primitive(s) whose mode is not TRIANGLES"));
    if (!singularNodes_.empty())
      note(printableLine(path_.string() + ": warning: skipped the meshes of " + singularNodes_ +
                   ": their world transform is singular (a scale of 0 hides them)"));
    if (!emissiveTextures_.empty())
      note(printableLine(path_.string() + ": warning: emissive textures are not supported: " + emissiveTextures_ +
                   " emit nothing"));
    std::stable_sort(cameraNodes_.begin(), cameraNodes_.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& [node, camera] : cameraNodes_) scene_.cameras.push_back(std::move(camera));
    return std::move(scene_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(printableLine(path_.string() + ": " + what));
  }

  void readMaterials() {
    for (size_t i = 0; i < model_.materials.size(); ++i) {
      const tinygltf::Material& m = model_.materials[i];
      const std::string where = label("material", m.name, int(i));
      SceneMaterial out;
      out.name = m.name;
      const std::vector<double>& base = m.pbrMetallicRoughness.baseColorFactor;
      if (base.size() >= 3) {
        if (!allFinite(base)) fail(where + ": baseColorFactor is not finite");
        out.baseColor = Rgb(base[0], base[1], base[2]);
      }
      if (m.emissiveFactor.size() >= 3) {
        if (!allFinite(m.emissiveFactor)) fail(where + ": emissiveFactor is not finite");
        double strength = 1.0;
        auto ext = m.extensions.find("KHR_materials_emissive_strength");
        if (ext != m.extensions.end() && ext->second.Has("emissiveStrength")) {
          const tinygltf::Value& s = ext->second.Get("emissiveStrength");
          if (!s.IsNumber() || !std::isfinite(s.GetNumberAsDouble()) || s.GetNumberAsDouble() < 0.0)
            fail(where + ": KHR_materials_emissive_strength.emissiveStrength must be a non-negative number");
          strength = s.GetNumberAsDouble();
        }
        out.emission = Rgb(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]) * strength;
        if (!allFinite({glm::value_ptr(out.emission), 3}))
          fail(where + ": emissiveFactor × emissiveStrength overflows");
        // The texture usually masks a few glowing details; its factor alone would light the whole surface.
        if (m.emissiveTexture.index >= 0 && out.isEmissive()) {
          out.emission = Rgb(0.0);
          emissiveTextures_ += (emissiveTextures_.empty() ? "" : ", ") + where;
        }
      }
      if (m.extras.Has("glossy")) {
        const tinygltf::Value& glossy = m.extras.Get("glossy");
        if (!glossy.IsObject()) fail(where + ": extras.glossy must be an object");
        out.glossyMaterial = stringField(glossy, "material", where);
        out.glossyFit = stringField(glossy, "fit", where);
      }
      scene_.materials.push_back(std::move(out));
    }
  }

  std::string stringField(const tinygltf::Value& object, const char* key, const std::string& where) const {
    if (!object.Has(key)) return {};
    const tinygltf::Value& v = object.Get(key);
    if (!v.IsString()) fail(where + ": extras.glossy." + key + " must be a string");
    return v.Get<std::string>();
  }

  // The default scene's roots; without a scene, every node that is nobody's child.
  std::vector<int> rootNodes() const {
    if (!model_.scenes.empty()) {
      const int s = model_.defaultScene >= 0 && size_t(model_.defaultScene) < model_.scenes.size()
                        ? model_.defaultScene
                        : 0;
      return model_.scenes[size_t(s)].nodes;
    }
    std::vector<char> isChild(model_.nodes.size(), 0);
    for (const tinygltf::Node& n : model_.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < isChild.size()) isChild[size_t(c)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < model_.nodes.size(); ++i)
      if (!isChild[i]) roots.push_back(int(i));
    return roots;
  }

  glm::dmat4 localMatrix(const tinygltf::Node& n, const std::string& where) const {
    if (!n.matrix.empty()) {
      if (n.matrix.size() != 16) fail(where + ": matrix must have 16 elements");
      const glm::dmat4 m = glm::make_mat4(n.matrix.data());  // both column-major
      // glTF's matrices are affine (TRS); positions are read as if the last row were 0, 0, 0, 1.
      if (!(std::abs(m[0][3]) <= 1e-6 && std::abs(m[1][3]) <= 1e-6 && std::abs(m[2][3]) <= 1e-6 &&
            std::abs(m[3][3] - 1.0) <= 1e-6))
        fail(where + ": matrix is not affine (its last row must be 0, 0, 0, 1)");
      return m;
    }
    glm::dmat4 m(1.0);
    if (!n.translation.empty()) {
      if (n.translation.size() != 3) fail(where + ": translation must have 3 elements");
      m = glm::translate(m, glm::make_vec3(n.translation.data()));
    }
    if (!n.rotation.empty()) {
      if (n.rotation.size() != 4) fail(where + ": rotation must have 4 elements");
      const glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // glTF stores x, y, z, w
      const double len = glm::length(q);
      if (!(len > 0.0) || !std::isfinite(len)) fail(where + ": rotation is not a valid quaternion");
      m *= glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) {
      if (n.scale.size() != 3) fail(where + ": scale must have 3 elements");
      m = glm::scale(m, glm::make_vec3(n.scale.data()));
    }
    return m;
  }

  // Depth first with an explicit stack, so a deep (or hostile) hierarchy cannot overflow the call stack.
  void walk(int root) {
    std::vector<std::pair<int, glm::dmat4>> stack{{root, glm::dmat4(1.0)}};
    while (!stack.empty()) {
      auto [index, parent] = stack.back();
      stack.pop_back();
      if (index < 0 || size_t(index) >= model_.nodes.size()) fail("node " + std::to_string(index) + " does not exist");
      const tinygltf::Node& node = model_.nodes[size_t(index)];
      const std::string where = label("node", node.name, index);
      if (visited_[size_t(index)]) fail(where + " is reached twice (the node hierarchy must be a tree)");
      visited_[size_t(index)] = 1;

      const glm::dmat4 world = parent * localMatrix(node, where);
      if (!allFinite({glm::value_ptr(world), 16})) fail(where + ": its transform is not finite");
      if (node.mesh >= 0) addMesh(node.mesh, world, where);
      if (node.camera >= 0) addCamera(node, index, world, where);
      if (const auto light = node.extensions.find("KHR_lights_punctual"); light != node.extensions.end())
        addLight(light->second, world, where);
      for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.emplace_back(*c, world);
    }
  }

  // A camera needs a position Embree can start rays from and three independent axes: a scale of 0 on it or
  // a parent, a zero matrix or an overflowing translation would give rays that are not finite.
  void checkCameraTransform(const glm::dmat4& world, const std::string& where) const {
    if (!withinScene(glm::dvec3(world[3]))) fail(where + ": the camera's position is beyond ±1e15 in world space");
    if (const char* why = singularity(world, 1e-9)) fail(where + ": the camera's world transform is singular (" + why + ")");
  }

  // A KHR_lights_punctual light, placed by its node (it shines down the node's −Z), within the bounds the
  // extension's specification sets.
  void addLight(const tinygltf::Value& extension, const glm::dmat4& world, const std::string& nodeWhere) {
    const tinygltf::Value& index = extension.Get("light");
    if (!index.IsInt()) fail(nodeWhere + ": its KHR_lights_punctual has no light index");
    const int i = index.GetNumberAsInt();
    if (i < 0 || size_t(i) >= model_.lights.size()) fail(nodeWhere + ": light " + std::to_string(i) + " does not exist");
    const tinygltf::Light& l = model_.lights[size_t(i)];
    SceneLight out{label("light", l.name, i) + " on " + nodeWhere, l.type};
    const std::string& where = out.name;
    if (l.type != "point" && l.type != "spot" && l.type != "directional")
      fail(where + ": type '" + l.type + "' is not point, spot or directional");
    const std::vector<double> color = l.color.empty() ? std::vector<double>{1.0, 1.0, 1.0} : l.color;
    if (color.size() != 3 || !allFinite(color) || *std::min_element(color.begin(), color.end()) < 0.0)
      fail(where + ": color must be three finite values ≥ 0");
    if (!(l.intensity >= 0.0) || !std::isfinite(l.intensity)) fail(where + ": intensity must be finite and ≥ 0");
    // Bounded as --env-constant's radiance is: a light of 1e300 would overflow the float image (or drop out
    // of light selection as infinite power) instead of lighting it; 1e12 is brighter than any lamp by far.
    const double brightest = *std::max_element(color.begin(), color.end()) * l.intensity;
    if (!(brightest <= kMaxLightIntensity))
      fail(where + formatted(": color × intensity is %g, beyond %g (candela for point and spot lights, lux for directional)",
                             brightest, kMaxLightIntensity));
    out.intensity = Rgb(color[0], color[1], color[2]) * l.intensity;
    if (l.type == "spot") {
      out.innerConeAngle = l.spot.innerConeAngle;
      out.outerConeAngle = l.spot.outerConeAngle;
      if (!(0.0 <= out.innerConeAngle && out.innerConeAngle <= out.outerConeAngle && out.outerConeAngle > 0.0 &&
            out.outerConeAngle <= kPi / 2.0))
        fail(where + ": its cone must have 0 ≤ innerConeAngle ≤ outerConeAngle ≤ π/2 (and outerConeAngle > 0)");
    }
    if (isSingular(world)) fail(where + ": its node's world transform is singular (a scale of 0 on it or a parent)");
    out.position = glm::dvec3(world[3]);
    if (!withinScene(out.position)) fail(where + ": its position is beyond ±1e15 in world space");
    out.direction = -glm::dvec3(world[2]) / robustLength(glm::dvec3(world[2]));
    scene_.lights.push_back(std::move(out));
  }

  void addCamera(const tinygltf::Node& node, int nodeIndex, const glm::dmat4& world, const std::string& where) {
    if (size_t(node.camera) >= model_.cameras.size())
      fail(where + ": camera " + std::to_string(node.camera) + " does not exist");
    checkCameraTransform(world, where);
    const tinygltf::Camera& c = model_.cameras[size_t(node.camera)];
    Camera out;
    out.name = !c.name.empty() ? c.name : node.name;
    out.cameraToWorld = world;
    if (c.type == "perspective") {
      out.type = Camera::Type::Perspective;
      out.yfov = c.perspective.yfov;
      out.aspectRatio = c.perspective.aspectRatio;
      if (!(out.yfov > 0.0 && out.yfov < kPi)) fail(where + ": camera yfov must be in (0, π)");
      if (!(out.aspectRatio >= 0.0 && std::isfinite(out.aspectRatio)))
        fail(where + ": camera aspectRatio must not be negative");
    } else if (c.type == "orthographic") {
      out.type = Camera::Type::Orthographic;
      out.xmag = c.orthographic.xmag;
      out.ymag = c.orthographic.ymag;
      if (!(std::isfinite(out.xmag) && std::isfinite(out.ymag) && out.xmag != 0.0 && out.ymag != 0.0))
        fail(where + ": orthographic camera xmag and ymag must be finite and non-zero");
      // Orthographic rays start across the view: its corners must stay where Embree can trace from.
      const glm::dvec3 reach = glm::abs(glm::dvec3(world[3])) + std::abs(out.xmag) * glm::abs(glm::dvec3(world[0])) +
                               std::abs(out.ymag) * glm::abs(glm::dvec3(world[1]));
      if (!withinScene(reach)) fail(where + ": the orthographic view reaches beyond ±1e15 in world space");
    } else {
      fail(where + ": camera type '" + c.type + "' is neither perspective nor orthographic");
    }
    cameraNodes_.emplace_back(nodeIndex, std::move(out));
  }

  void addMesh(int meshIndex, const glm::dmat4& world, const std::string& nodeWhere) {
    if (size_t(meshIndex) >= model_.meshes.size())
      fail(nodeWhere + ": mesh " + std::to_string(meshIndex) + " does not exist");
    // A node scaled to 0 (how animated models hide parts) flattens its meshes to nothing: those primitives
    // are skipped with one warning, where a mesh's own zero-area triangles are an error. A scale of 0 on one
    // axis may leave a flat card, which is kept.
    const bool singular = isSingular(world);
    bool skipped = false;
    const tinygltf::Mesh& mesh = model_.meshes[size_t(meshIndex)];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = mesh.primitives[p];
      // tinygltf leaves -1 only when "mode" is absent, which glTF defines as TRIANGLES.
      if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) {
        ++skippedPrimitives_;
        continue;
      }
      const std::string where =
          nodeWhere + " / " + label("mesh", mesh.name, meshIndex) + " / primitive " + std::to_string(p);
      if (!addPrimitive(prim, world, where, singular)) skipped = true;
    }
    if (skipped) singularNodes_ += (singularNodes_.empty() ? "" : ", ") + nodeWhere;
  }

  AccessorData accessor(int index, int type, std::initializer_list<int> componentTypes, const std::string& what,
                        const std::string& where) const {
    if (index < 0 || size_t(index) >= model_.accessors.size())
      fail(where + ": " + what + " accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& a = model_.accessors[size_t(index)];
    const std::string name = where + ": " + what + " accessor " + std::to_string(index);
    if (a.type != type ||
        std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end()) {
      fail(name + " is " + typeName(a.type) + " of " + componentTypeName(a.componentType) + ", expected " +
           typeName(type) + " of " + joined(componentTypes, " or ", componentTypeName));
    }
    if (a.sparse.isSparse) fail(name + " is sparse, which is not supported");

    AccessorData out;
    out.count = a.count;
    out.componentType = a.componentType;
    const size_t elementSize =
        size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType))) * size_t(tinygltf::GetNumComponentsInType(uint32_t(type)));
    out.stride = elementSize;
    if (a.bufferView < 0) return out;  // glTF: an accessor without a buffer view reads as zeros

    if (size_t(a.bufferView) >= model_.bufferViews.size())
      fail(name + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size())
      fail(name + ": buffer " + std::to_string(view.buffer) + " does not exist");
    const std::vector<unsigned char>& buffer = model_.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      fail(name + ": its buffer view runs past the end of buffer " + std::to_string(view.buffer));
    if (view.byteStride != 0) {
      if (view.byteStride < elementSize) fail(name + ": byteStride is smaller than an element");
      out.stride = view.byteStride;
    }
    // Overflow-safe form of byteOffset + (count − 1)·stride + elementSize ≤ byteLength.
    const size_t length = view.byteLength;
    if (a.count > 0 && (a.byteOffset > length || elementSize > length - a.byteOffset ||
                        (a.count - 1) > (length - a.byteOffset - elementSize) / out.stride))
      fail(name + " runs past the end of its buffer view");
    out.first = buffer.data() + view.byteOffset + a.byteOffset;
    return out;
  }

  // False when a singular transform left it no triangle to draw.
  bool addPrimitive(const tinygltf::Primitive& prim, const glm::dmat4& world, const std::string& where, bool singular) {
    Mesh mesh;
    mesh.name = where;

    auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) fail(where + ": has no POSITION attribute");
    const AccessorData positions =
        accessor(position->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "POSITION", where);
    if (positions.count == 0) fail(where + ": has no vertices");
    if (positions.count > size_t(UINT32_MAX)) fail(where + ": has too many vertices");
    mesh.positions.resize(positions.count);
    for (size_t i = 0; i < positions.count; ++i) {
      const glm::dvec3 p(positions.vec3(i));
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(where + ": position " + std::to_string(i) + " is not finite");
      const glm::dvec3 wd(world * glm::dvec4(p, 1.0));
      // Rays leave hits from these points, and Embree refuses origins beyond about 1.8e18.
      if (!withinScene(wd))
        fail(where + ": position " + std::to_string(i) + " is beyond ±1e15 in world space (is its node's transform overflowing?)");
      const glm::vec3 w(wd);
      mesh.positions[i] = w;
    }

    std::vector<uint32_t> indices;
    if (prim.indices >= 0) {
      const AccessorData ia = accessor(prim.indices, TINYGLTF_TYPE_SCALAR,
                                       {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                                       "indices", where);
      if (ia.count % 3 != 0) fail(where + ": index count " + std::to_string(ia.count) + " is not a multiple of 3");
      indices.resize(ia.count);
      for (size_t i = 0; i < ia.count; ++i) {
        indices[i] = ia.index(i);
        if (indices[i] >= positions.count)
          fail(where + ": index " + std::to_string(indices[i]) + " is out of range (" +
               std::to_string(positions.count) + " vertices)");
      }
    } else {
      if (positions.count % 3 != 0)
        fail(where + ": vertex count " + std::to_string(positions.count) + " is not a multiple of 3");
      indices.resize(positions.count);
      for (size_t i = 0; i < positions.count; ++i) indices[i] = uint32_t(i);
    }

    // A mirroring transform turns counter-clockwise triangles clockwise; swapping two corners keeps the
    // winding (and so the geometric normal) facing outward.
    const glm::dmat3 linear(world);
    const bool mirrored = glm::determinant(linear) < 0.0;
    mesh.indices.reserve(indices.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
      uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
      if (mirrored) std::swap(b, c);
      const glm::dvec3 p0(mesh.positions[a]), p1(mesh.positions[b]), p2(mesh.positions[c]);
      if (!(glm::length(glm::cross(p1 - p0, p2 - p0)) > 0.0)) continue;  // zero area: nothing to hit
      mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
    if (mesh.indices.empty() && singular && !indices.empty()) return false;
    if (mesh.indices.empty())
      fail(where + (indices.empty() ? ": has no triangles" : ": all its triangles have zero area"));

    auto normal = prim.attributes.find("NORMAL");
    if (normal != prim.attributes.end()) {
      const AccessorData na =
          accessor(normal->second, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "NORMAL", where);
      if (na.count != positions.count)
        fail(where + ": has " + std::to_string(na.count) + " normals for " + std::to_string(positions.count) +
             " vertices");
      const glm::dmat3 normalMatrix = glm::inverseTranspose(linear);
      mesh.normals.resize(na.count);
      for (size_t i = 0; i < na.count; ++i) {
        const glm::dvec3 n(na.vec3(i));
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z))
          fail(where + ": normal " + std::to_string(i) + " is not finite");
        const glm::dvec3 w = normalMatrix * n;
        const double len = glm::length(w);
        // A zero normal stays zero: the Embree scene falls back to the geometric normal where it matters.
        mesh.normals[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(w / len) : glm::vec3(0.0f);
      }
    }

    if (prim.material >= 0) {
      if (size_t(prim.material) >= scene_.materials.size())
        fail(where + ": material " + std::to_string(prim.material) + " does not exist");
      mesh.material = prim.material;
    }
    scene_.meshes.push_back(std::move(mesh));
    return true;
  }

  // |v| without the underflow of squaring components of 1e-200 (a node scaled that small is not singular).
  static double robustLength(const glm::dvec3& v) {
    const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return m > 0.0 && std::isfinite(m) ? m * glm::length(v / m) : m;
  }

  // Why the linear part is singular (a scale of 0 on some axis): a zero column, or unit columns whose
  // triple product is within `tolerance` of 0; null when it is not.
  static const char* singularity(const glm::dmat4& world, double tolerance) {
    glm::dvec3 c[3];
    for (int i = 0; i < 3; ++i) {
      const double len = robustLength(glm::dvec3(world[i]));
      if (!(len > 0.0) || !std::isfinite(len)) return "a scale of 0 or a zero matrix on it or a parent";
      c[i] = glm::dvec3(world[i]) / len;
    }
    return std::abs(glm::dot(c[0], glm::cross(c[1], c[2]))) > tolerance ? nullptr : "its axes are coplanar";
  }
  static bool isSingular(const glm::dmat4& world) { return singularity(world, 1e-12) != nullptr; }

  // Embree refuses ray origins beyond about 1.8e18; points past ±1e15 are refused first.
  static bool withinScene(const glm::dvec3& p) {
    return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}) <= kMaxSceneCoordinate;
  }

  const std::filesystem::path& path_;
  const tinygltf::Model& model_;
  SceneDescription scene_;
  std::vector<char> visited_;
  std::vector<std::pair<int, Camera>> cameraNodes_;
  int skippedPrimitives_ = 0;
  std::string singularNodes_, emissiveTextures_;
};

// tinygltf's file system, through input_file.h: a name is there if anything is (so that a FIFO or folder is
// refused by readWholeFile, naming it, rather than reported missing), and read only if it is a regular file
// of at most kMaxBufferBytes.
constexpr std::uintmax_t kMaxBufferBytes = std::uintmax_t(1) << 31;

bool fileExists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}

// `digest`: a Digest every file read is added to (the scene file itself, then its buffers): what the pixels
// depend on, for SceneDescription::digest.
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* digest) {
  try {
    const std::string bytes = readInputFile(path, kMaxBufferBytes, "glTF buffer");
    if (digest) static_cast<Digest*>(digest)->add(bytes);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    if (err) *err += e.what();
    return false;
  }
}

bool hasGlbMagic(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  in.read(magic, sizeof magic);
  return in.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
}

}  // namespace

SceneDescription loadGltf(const std::filesystem::path& path) {
  requireInputFile(path, "glTF scene");
  preflightGltf(path);

  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(ignoreImage, nullptr);
  // The files the scene names (its buffers) are inputs too: tinygltf's own reader would open a FIFO and wait.
  Digest digest;
  gltf.SetFsCallbacks({fileExists, tinygltf::ExpandFilePath, readWholeFile, nullptr, &digest});
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    ok = hasGlbMagic(path) ? gltf.LoadBinaryFromFile(&model, &err, &warn, path.string())
                           : gltf.LoadASCIIFromFile(&model, &err, &warn, path.string());
  } catch (const std::exception& e) {
    err = e.what();
  }
  if (!ok) {
    const std::string why = !err.empty() ? err : !warn.empty() ? warn : "cannot read it as glTF 2.0";
    throw InputError(printableLine(path.string() + ": " + why));
  }
  if (!warn.empty()) note(printableLine(path.string() + ": warning: " + warn));
  SceneDescription scene = GltfReader(path, model).read();
  scene.digest = digest.hex();
  return scene;
}

}  // namespace glossy
