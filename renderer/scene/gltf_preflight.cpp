#include "renderer/scene/gltf_preflight.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

namespace glossy {

namespace {

// Required extensions glossy reads (punctual lights, emissive strength) or whose absence of support changes
// nothing the renderer draws (textures, so their transforms, are not used at all).
constexpr std::array kSupportedRequired = {"KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_texture_transform"};

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw InputError(printableLine(path.string() + ": " + what));
}

uint32_t u32(const std::string& bytes, size_t at) {
  uint32_t x = 0;
  std::memcpy(&x, bytes.data() + at, sizeof x);
  return x;  // GLB is little-endian, as every platform glossy builds on
}

// The JSON text of a .gltf, or of a GLB's first chunk, which the GLB format requires to be the JSON.
std::string jsonText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open it");
  std::string header(20, '\0');
  in.read(header.data(), std::streamsize(header.size()));
  header.resize(size_t(in.gcount()));
  if (header.compare(0, 4, "glTF") != 0) {
    in.clear();
    in.seekg(0);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  if (header.size() < 20) fail(path, "GLB header is truncated");
  if (u32(header, 4) != 2) fail(path, "GLB container version " + std::to_string(u32(header, 4)) + " is not 2");
  if (u32(header, 16) != 0x4E4F534Au) fail(path, "GLB's first chunk is not JSON");
  const uint32_t length = u32(header, 12);
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || uintmax_t(length) > size - 20) fail(path, "GLB's JSON chunk runs past the end of the file");
  std::string text(length, '\0');
  in.read(text.data(), std::streamsize(length));
  if (size_t(in.gcount()) != length) fail(path, "GLB's JSON chunk cannot be read");
  return text;
}

// KHR_lights_punctual's lights, each field of the type the extension's schema gives it: tinygltf reads a
// field of another type as if it were absent, so `"intensity": "1e300"` or `"color": "red"` would light the
// scene with the default instead of being refused.
void checkPunctualLights(const std::filesystem::path& path, const nlohmann::json& doc) {
  const auto extensions = doc.find("extensions");
  if (extensions == doc.end()) return;
  if (!extensions->is_object()) fail(path, "extensions is not an object");
  const auto punctual = extensions->find("KHR_lights_punctual");
  if (punctual == extensions->end()) return;
  if (!punctual->is_object()) fail(path, "extensions.KHR_lights_punctual is not an object");
  const auto lights = punctual->find("lights");
  if (lights == punctual->end()) return;
  if (!lights->is_array()) fail(path, "KHR_lights_punctual.lights is not an array");
  for (size_t i = 0; i < lights->size(); ++i) {
    const nlohmann::json& light = (*lights)[i];
    // Named as the loader names a light: "light 'Lamp'", or "light 3" when it has no name.
    std::string where = "light " + std::to_string(i);
    if (!light.is_object()) fail(path, where + " of KHR_lights_punctual is not an object");
    if (const auto name = light.find("name"); name != light.end()) {
      if (!name->is_string()) fail(path, where + ": name must be a string, not " + name->type_name());
      if (!name->get<std::string>().empty()) where = "light '" + shortened(name->get<std::string>()) + "'";
    }
    const auto field = [&](const nlohmann::json& object, const char* key, const char* what, bool (nlohmann::json::*is)() const noexcept,
                           const std::string& prefix = "") {
      const auto f = object.find(key);
      if (f != object.end() && !((*f).*is)()) fail(path, where + ": " + prefix + key + " must be " + what + ", not " + f->type_name());
    };
    const auto type = light.find("type");
    if (type == light.end()) fail(path, where + " has no type (point, spot or directional)");
    field(light, "type", "a string", &nlohmann::json::is_string);
    field(light, "intensity", "a number", &nlohmann::json::is_number);
    field(light, "range", "a number", &nlohmann::json::is_number);
    field(light, "spot", "an object", &nlohmann::json::is_object);
    if (const auto color = light.find("color"); color != light.end())
      if (!color->is_array() || color->size() != 3 || !std::all_of(color->begin(), color->end(), [](const nlohmann::json& c) { return c.is_number(); }))
        fail(path, where + ": color must be an array of three numbers");
    if (const auto spot = light.find("spot"); spot != light.end()) {
      field(*spot, "innerConeAngle", "a number", &nlohmann::json::is_number, "spot.");
      field(*spot, "outerConeAngle", "a number", &nlohmann::json::is_number, "spot.");
    }
  }
}

}  // namespace

void preflightGltf(const std::filesystem::path& path) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(jsonText(path));
  } catch (const nlohmann::json::exception& e) {
    std::string why = e.what();
    if (const size_t end = why.find("] "); why.rfind("[json.exception", 0) == 0 && end != std::string::npos)
      why.erase(0, end + 2);  // the library's tag says nothing to the user
    fail(path, "is not valid glTF JSON: " + why);
  }
  if (!doc.is_object()) fail(path, "is not a glTF document (its JSON is not an object)");

  if (const auto required = doc.find("extensionsRequired"); required != doc.end()) {
    if (!required->is_array()) fail(path, "extensionsRequired is not an array");
    for (const nlohmann::json& e : *required) {
      if (!e.is_string()) fail(path, "extensionsRequired holds a non-string entry");
      const std::string name = e.get<std::string>();
      if (std::find(kSupportedRequired.begin(), kSupportedRequired.end(), name) != kSupportedRequired.end()) continue;
      std::string hint;
      if (name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression")
        hint = " (decompress its meshes first, e.g. gltf-transform copy)";
      fail(path, "requires extension " + name + ", which glossy does not support" + hint);
    }
  }

  const auto asset = doc.find("asset");
  if (asset == doc.end() || !asset->is_object()) fail(path, "has no asset object (glTF 2.0 requires asset.version)");
  const auto version = asset->find("version");
  if (version == asset->end() || !version->is_string()) fail(path, "asset.version is missing or not a string");
  const std::string v = version->get<std::string>();
  if (v.rfind("2.", 0) != 0) fail(path, "asset.version is '" + v + "'; glossy reads glTF 2.x only");
  checkPunctualLights(path, doc);
}

}  // namespace glossy
