// A scene as the renderer sees it: triangle meshes flattened to world space, their materials, and the
// cameras, loaded from glTF 2.0 (shared/spec/interfaces.md). World space is glTF's: Y up, metres.
#pragma once

#include "materials/core/types.h"

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glossy {

// The farthest a vertex or a camera may be from the origin on any axis, in metres. Embree refuses a ray
// whose origin is beyond about 1.8e18 (its ray.valid() assertion aborts the program); this leaves room for
// the automatic camera's distance and for rays that start a margin off a surface.
constexpr double kMaxSceneCoordinate = 1e15;

struct SceneMaterial {
  std::string name;
  Rgb baseColor{0.8};    // Lambertian albedo when no glossy material is bound
  Rgb emission{0.0};     // emissiveFactor × KHR_materials_emissive_strength; non-zero makes an area light
  // extras.glossy binding, or empty: {"material": "materials/library/merl/x.toml", "fit": "microfacet:E2"}; the
  // material path is as written in the file (resolved by the caller against the scene's folder, then cwd).
  std::string glossyMaterial;
  std::string glossyFit;
  bool isEmissive() const { return emission.r > 0.0 || emission.g > 0.0 || emission.b > 0.0; }
};

struct Mesh {
  std::string name;                // "node 'Sphere' / mesh 'Sphere' / primitive 0", for messages
  std::vector<glm::vec3> positions;  // world space
  std::vector<glm::vec3> normals;    // world space, unit; empty = use geometric normals
  std::vector<uint32_t> indices;     // 3 per triangle, into positions (non-indexed input is expanded)
  int material = -1;                 // index into SceneDescription::materials; -1 = default grey Lambertian
};

struct Camera {
  enum class Type { Perspective, Orthographic };
  std::string name;
  Type type = Type::Perspective;
  glm::dmat4 cameraToWorld{1.0};  // glTF camera: looks down −Z, +Y up, in its node's frame
  double yfov = 0.6;              // perspective: vertical field of view, radians
  double aspectRatio = 0.0;       // perspective: 0 = use the image's
  double xmag = 1.0, ymag = 1.0;  // orthographic: half extents of the view
};

// A light placed by a node: glTF KHR_lights_punctual's point, spot and directional lights. A light type
// (renderer/lights/) renders the entries of its `type`.
struct SceneLight {
  std::string name;  // "light 'Lamp' on node 'N'", for messages
  std::string type;  // "point", "spot", "directional"
  Rgb intensity{0.0};  // color × intensity: candela (point, spot) or lux (directional); docs/rendering.md
  Vec3 position{0.0};
  Vec3 direction{0.0, 0.0, -1.0};  // unit, where it shines: its node's −Z
  double innerConeAngle = 0.0, outerConeAngle = kPi / 4.0;  // spot, radians from direction
};

struct SceneDescription {
  std::filesystem::path source;
  std::string digest;  // of the bytes of every file loadGltf read (the scene, its buffers): util/digest.h
  std::vector<Mesh> meshes;
  std::vector<SceneMaterial> materials;
  std::vector<Camera> cameras;  // in glTF node order; the first is the default
  std::vector<SceneLight> lights;
};

// Loads .gltf (external or embedded buffers) or .glb. Throws InputError naming the file and the
// node/mesh for malformed or degenerate input (no triangles at all, bad indices, positions or cameras that
// are not finite or beyond kMaxSceneCoordinate, a camera whose transform is singular, a required extension
// it does not support, a version other than 2.x, a `scene` that does not exist, a light of another type, with an intensity or color that is negative or not finite,
// a spot cone outside 0 ≤ inner ≤ outer ≤ π/2, or on a singular transform). Skipped with a warning on
// stderr, if other geometry remains: primitives that are not TRIANGLES, primitives a singular transform
// (scale 0) leaves without area. Emissive textures are not read: a material with one emits nothing (warned).
SceneDescription loadGltf(const std::filesystem::path& path);

}  // namespace glossy
