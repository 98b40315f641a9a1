// glTF documents assembled by tests: JSON plus one binary buffer, written as .gltf (external or embedded
// buffer) or .glb.
#pragma once

#include "tests/support/test_support.h"

#include <nlohmann/json.hpp>

#include <glm/vec3.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::test {

constexpr int kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125, kFloat = 5126;

std::string base64(const std::string& bytes);

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

struct GltfDoc {
  nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
  std::string bin;

  int push(const char* array, nlohmann::json item);
  int addView(const std::string& bytes, int stride = 0);
  int addAccessor(int view, int componentType, const char* type, size_t count, size_t byteOffset = 0);
  int addPositions(const std::vector<glm::vec3>& p);
  int addIndices(const std::vector<uint32_t>& indices, int componentType = kUnsignedInt);
  // A mesh of one primitive and a root node holding it; returns the node.
  int addMeshNode(const std::string& name, nlohmann::json primitive, nlohmann::json node = nlohmann::json::object());
  void setScene(const std::vector<int>& roots);

  nlohmann::json withBuffer(nlohmann::json uri) const;
  std::filesystem::path writeExternal(const TempDir& dir, const std::string& name) const;
  std::filesystem::path writeEmbedded(const TempDir& dir, const std::string& name) const;
  std::filesystem::path writeGlb(const TempDir& dir, const std::string& name) const;
};

// A box (centre, full size) as a TRIANGLES primitive of `doc`: 24 vertices, one face's four per side, with
// outward per-face normals unless `normals` is false; indices of `indexType`, or none (36 vertices) when 0.
nlohmann::json boxPrimitive(GltfDoc& doc, glm::vec3 centre, glm::vec3 size, bool normals = true,
                            int indexType = kUnsignedInt);

}  // namespace glossy::test
