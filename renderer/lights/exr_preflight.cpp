#include "renderer/lights/exr_preflight.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

namespace glossy {

namespace {

constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr uint32_t kMultipart = 0x1000;  // version flag: a list of headers, ended by an empty one
constexpr int32_t kMaxChannelList = 1 << 20;  // 17 bytes and its name per channel: tens of thousands of channels

// Reads a NUL-terminated name of at most 255 characters (OpenEXR's long-name limit); false when the file
// ends first or the name is longer.
bool readName(std::istream& in, std::string& name) {
  name.clear();
  for (char c; in.get(c);) {
    if (c == '\0') return true;
    if (name.size() == 255) return false;
    name += c;
  }
  return false;
}

// A channel list (type "chlist"): per channel its NUL-terminated name, then its pixel type (int32), linear
// flag (1 byte), 3 reserved bytes and x and y sampling (int32 each); an empty name ends it. OpenEXR reads
// the entries until that empty name whatever size the attribute claims, so the list must end exactly at its
// claimed size for the types checked here to be the ones OpenEXR sees. "" when it does and every pixel type
// is UINT (0), HALF (1) or FLOAT (2); else what is wrong.
std::string channelListProblem(const std::string& list) {
  for (size_t at = 0; at < list.size();) {
    const size_t end = list.find('\0', at);
    if (end == std::string::npos) break;
    if (end == at) return at + 1 == list.size() ? "" : "channel list ends before the size it claims";
    const std::string name = list.substr(at, end - at);
    if (list.size() - (end + 1) < 16) break;
    int32_t type;
    std::memcpy(&type, list.data() + end + 1, sizeof type);
    if (type < 0 || type > 2)
      return "channel '" + name + "' has pixel type " + std::to_string(type) + ", not UINT (0), HALF (1) or FLOAT (2)";
    at = end + 1 + 16;
  }
  return "channel list runs past the size it claims";
}

}  // namespace

void preflightExr(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[8];
  if (!in.read(reinterpret_cast<char*>(head), sizeof head) || std::memcmp(head, kMagic, sizeof kMagic) != 0) return;
  // Names come from the file: printableLine keeps the message one readable line.
  const auto fail = [&](const std::string& what) {
    return InputError(printableLine(path.string() + ": OpenEXR header " + what));
  };
  std::error_code ec;
  const uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw fail("cannot be read");
  uint32_t version;
  std::memcpy(&version, head + 4, sizeof version);  // little-endian, as every platform glossy builds on

  for (;;) {
    std::string name, type;
    bool empty = true;
    for (;;) {
      if (!readName(in, name)) throw fail("is truncated or has an attribute name over 255 characters");
      if (name.empty()) break;
      empty = false;
      if (!readName(in, type)) throw fail("attribute '" + name + "' has a truncated or overlong type name");
      int32_t bytes;
      if (!in.read(reinterpret_cast<char*>(&bytes), sizeof bytes)) throw fail("attribute '" + name + "' is truncated");
      const auto at = static_cast<uintmax_t>(in.tellg());
      if (bytes < 0 || uintmax_t(bytes) > size - at)
        throw fail("attribute '" + name + "' claims " + std::to_string(bytes) + " bytes, more than the " +
                   std::to_string(size - at) + " left in the file");
      if (type == "chlist") {
        // OpenEXR passes on any pixel type, and OpenImageIO aborts the program on one it does not know.
        if (bytes > kMaxChannelList)
          throw fail("channel list '" + name + "' is " + std::to_string(bytes) + " bytes, more than the " +
                     std::to_string(kMaxChannelList) + " of any real file");
        std::string list(size_t(bytes), '\0');
        if (!in.read(list.data(), bytes)) throw fail("attribute '" + name + "' cannot be read");
        if (const std::string problem = channelListProblem(list); !problem.empty()) throw fail(problem);
      } else {
        in.seekg(bytes, std::ios::cur);
      }
    }
    // A single-part file has one header; a multipart file's list ends with an empty header.
    if (!(version & kMultipart) || empty) return;
  }
}

}  // namespace glossy
