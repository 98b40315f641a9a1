#include "tests/support/gltf_doc.h"

namespace glossy::test {

using nlohmann::json;

std::string base64(const std::string& bytes) {
  static const char* const digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8 | uint8_t(bytes[i + 2]);
    for (int s = 18; s >= 0; s -= 6) out += digits[(n >> s) & 63];
  }
  if (i + 1 == bytes.size()) {
    const uint32_t n = uint32_t(uint8_t(bytes[i])) << 16;
    out += {digits[n >> 18], digits[(n >> 12) & 63], '=', '='};
  } else if (i + 2 == bytes.size()) {
    const uint32_t n = uint32_t(uint8_t(bytes[i])) << 16 | uint32_t(uint8_t(bytes[i + 1])) << 8;
    out += {digits[n >> 18], digits[(n >> 12) & 63], digits[(n >> 6) & 63], '='};
  }
  return out;
}

int GltfDoc::push(const char* array, json item) {
  doc[array].push_back(std::move(item));
  return int(doc[array].size() - 1);
}
int GltfDoc::addView(const std::string& bytes, int stride) {
  while (bin.size() % 4 != 0) bin += '\0';
  json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes.size()}};
  if (stride) view["byteStride"] = stride;
  bin += bytes;
  return push("bufferViews", view);
}
int GltfDoc::addAccessor(int view, int componentType, const char* type, size_t count, size_t byteOffset) {
  return push("accessors", {{"bufferView", view},
                            {"componentType", componentType},
                            {"type", type},
                            {"count", count},
                            {"byteOffset", byteOffset}});
}
int GltfDoc::addPositions(const std::vector<glm::vec3>& p) {
  return addAccessor(addView(bytesOf(p)), kFloat, "VEC3", p.size());
}
int GltfDoc::addIndices(const std::vector<uint32_t>& indices, int componentType) {
  std::string bytes;
  for (uint32_t i : indices) {
    if (componentType == kUnsignedByte) bytes += char(uint8_t(i));
    if (componentType == kUnsignedShort) bytes += bytesOf(std::vector<uint16_t>{uint16_t(i)});
    if (componentType == kUnsignedInt) bytes += bytesOf(std::vector<uint32_t>{i});
  }
  return addAccessor(addView(bytes), componentType, "SCALAR", indices.size());
}
int GltfDoc::addMeshNode(const std::string& name, json primitive, json node) {
  const int mesh = push("meshes", {{"name", name}, {"primitives", json::array({primitive})}});
  node["mesh"] = mesh;
  node["name"] = name + "Node";
  return push("nodes", node);
}
void GltfDoc::setScene(const std::vector<int>& roots) {
  doc["scenes"] = json::array({{{"nodes", roots}}});
  doc["scene"] = 0;
}

json GltfDoc::withBuffer(json uri) const {
  json d = doc;
  json buffer = {{"byteLength", bin.size()}};
  if (!uri.is_null()) buffer["uri"] = uri;
  d["buffers"] = json::array({buffer});
  return d;
}
std::filesystem::path GltfDoc::writeExternal(const TempDir& dir, const std::string& name) const {
  writeText(dir / (name + ".bin"), bin);
  writeText(dir / (name + ".gltf"), withBuffer(name + ".bin").dump());
  return dir / (name + ".gltf");
}
std::filesystem::path GltfDoc::writeEmbedded(const TempDir& dir, const std::string& name) const {
  writeText(dir / (name + ".gltf"), withBuffer("data:application/octet-stream;base64," + base64(bin)).dump());
  return dir / (name + ".gltf");
}
std::filesystem::path GltfDoc::writeGlb(const TempDir& dir, const std::string& name) const {
  std::string text = withBuffer(nullptr).dump();
  while (text.size() % 4 != 0) text += ' ';
  std::string data = bin;
  while (data.size() % 4 != 0) data += '\0';
  auto u32 = [](uint32_t x) { return bytesOf(std::vector<uint32_t>{x}); };
  const std::string glb = "glTF" + u32(2) + u32(uint32_t(12 + 8 + text.size() + 8 + data.size())) +
                          u32(uint32_t(text.size())) + u32(0x4E4F534A) + text + u32(uint32_t(data.size())) +
                          u32(0x004E4942) + data;
  writeText(dir / (name + ".glb"), glb);
  return dir / (name + ".glb");
}

json boxPrimitive(GltfDoc& doc, glm::vec3 centre, glm::vec3 size, bool normals, int indexType) {
  std::vector<glm::vec3> p, n;
  std::vector<uint32_t> idx;
  for (int axis = 0; axis < 3; ++axis)
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 normal(0.0f);
      normal[axis] = side;
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const auto base = uint32_t(p.size());
      for (auto [a, b] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
        glm::vec3 q = normal;
        q[u] = a;
        q[v] = b * side;  // counter-clockwise seen from outside on both sides
        p.push_back(centre + 0.5f * size * q);
        n.push_back(normal);
      }
      for (uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) idx.push_back(base + k);
    }
  if (indexType == 0) {
    std::vector<glm::vec3> soup, soupNormals;
    for (uint32_t i : idx) {
      soup.push_back(p[i]);
      soupNormals.push_back(n[i]);
    }
    p = soup;
    n = soupNormals;
  }
  json prim = {{"attributes", {{"POSITION", doc.addPositions(p)}}}};
  if (normals) prim["attributes"]["NORMAL"] = doc.addPositions(n);
  if (indexType != 0) prim["indices"] = doc.addIndices(idx, indexType);
  return prim;
}

}  // namespace glossy::test
