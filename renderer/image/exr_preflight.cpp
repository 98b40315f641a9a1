#include "renderer/image/exr_preflight.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"

#include <cstdint>
#include <iterator>
#include <limits>
#include <cstring>
#include <fstream>
#include <string>
#include <utility>

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

// The types OpenEXR reads as a fixed number of bytes whatever size the attribute claims: a claim that differs
// would leave OpenEXR reading the rest of the header from another place than this check does.
constexpr std::pair<const char*, int32_t> kFixedSizes[] = {
    {"box2i", 16},       {"box2f", 16},    {"chromaticities", 32}, {"compression", 1}, {"double", 8},
    {"envmap", 1},       {"float", 4},     {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
    {"m33f", 36},        {"m33d", 72},     {"m44f", 64},           {"m44d", 128},      {"rational", 8},
    {"tiledesc", 9},     {"timecode", 8},  {"v2i", 8},             {"v2f", 8},         {"v2d", 16},
    {"v3i", 12},         {"v3f", 12},      {"v3d", 24},            {"deepImageState", 1}};

int32_t fixedSize(const std::string& type) {
  for (const auto& [name, bytes] : kFixedSizes)
    if (type == name) return bytes;
  return -1;
}

int32_t littleEndianInt(const std::string& bytes, size_t at) {
  int32_t v;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

// What OpenEXR would allocate from the contents of a variable-size attribute rather than from its claimed
// size: a string vector's strings (each an int32 length, then the bytes) and a preview image (width and
// height, then 4 bytes per pixel). "" when every such size stays within the attribute.
std::string contentProblem(const std::string& type, const std::string& value) {
  if (type == "stringvector") {
    for (size_t at = 0; at < value.size();) {
      if (value.size() - at < 4) return "string vector ends inside a string's length";
      const int32_t length = littleEndianInt(value, at);
      at += 4;
      if (length < 0 || uintmax_t(length) > value.size() - at)
        return "string vector holds a string of " + std::to_string(length) + " bytes, more than the " +
               std::to_string(value.size() - at) + " left in it";
      at += size_t(length);
    }
  } else if (type == "preview") {
    if (value.size() < 8) return "preview image is shorter than its size";
    const auto width = uint32_t(littleEndianInt(value, 0)), height = uint32_t(littleEndianInt(value, 4));
    if (uint64_t(width) * height * 4 != value.size() - 8)
      return "preview image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels does not fit its " +
             std::to_string(value.size()) + " bytes";
  }
  return "";
}

// Attributes whose contents are checked, read whole (their claimed size is within the file's).
bool checksContents(const std::string& type) {
  return type == "chlist" || type == "stringvector" || type == "preview" || type == "box2i" || type == "compression" ||
         type == "tiledesc";
}

// What OpenEXR decodes at once, a chunk (a block of scanlines, or a tile), whose buffers it allocates when it
// opens the file, before any pixel is read: a header of a few bytes that claims a data window of 2^30
// columns would make it take gigabytes there. Above this, no image glossy writes or reads: a sheet of 7
// panels 8192 pixels wide, in float with its error maps, takes 132 MiB per 16-line chunk.
constexpr uint64_t kMaxChunkBytes = uint64_t(512) << 20;

// Scanlines per chunk of each OpenEXR compression (by its code: none, RLE, ZIPS, ZIP, PIZ, PXR24, B44, B44A,
// DWAA, DWAB); 0 for a code OpenEXR does not know, which it refuses itself.
int linesPerChunk(int compression) {
  constexpr int kLines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
  return compression >= 0 && compression < int(std::size(kLines)) ? kLines[compression] : 0;
}

// Bytes per pixel of a channel list that channelListProblem accepted: HALF 2, UINT and FLOAT 4.
uint64_t pixelBytes(const std::string& list) {
  uint64_t bytes = 0;
  for (size_t at = 0; at < list.size();) {
    const size_t end = list.find('\0', at);
    if (end == at) break;
    bytes += littleEndianInt(list, end + 1) == 1 ? 2 : 4;
    at = end + 1 + 16;
  }
  return bytes;
}

// What one header says of its chunks, as far as the preflight read it.
struct ChunkShape {
  int64_t width = 0;            // of the data window
  int compression = 0;
  uint64_t pixelBytes = 0;      // all channels
  int64_t tileWidth = 0, tileHeight = 0;  // a tiled file's
};

// The bytes of one chunk of the header's image, in 64-bit arithmetic, saturating; 0 where the header lacks
// what it takes (OpenEXR refuses such a header itself).
uint64_t chunkBytes(const ChunkShape& c) {
  if (c.width <= 0 && c.tileWidth <= 0) return 0;
  const uint64_t pixels = c.tileWidth > 0 ? uint64_t(c.tileWidth) * uint64_t(c.tileHeight)  // below 2^64
                                          : uint64_t(c.width) * uint64_t(linesPerChunk(c.compression));
  if (c.pixelBytes > 0 && pixels > std::numeric_limits<uint64_t>::max() / c.pixelBytes) return std::numeric_limits<uint64_t>::max();
  return pixels * c.pixelBytes;
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
    ChunkShape chunk;
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
      if (const int32_t fixed = fixedSize(type); fixed >= 0 && bytes != fixed)
        throw fail("attribute '" + name + "' of type " + type + " claims " + std::to_string(bytes) + " bytes, not its " +
                   std::to_string(fixed));
      if (checksContents(type)) {
        if (type == "chlist" && bytes > kMaxChannelList)
          throw fail("channel list '" + name + "' is " + std::to_string(bytes) + " bytes, more than the " +
                     std::to_string(kMaxChannelList) + " of any real file");
        std::string value(size_t(bytes), '\0');
        if (!in.read(value.data(), bytes)) throw fail("attribute '" + name + "' cannot be read");
        // OpenEXR passes on any pixel type, and OpenImageIO aborts the program on one it does not know.
        const std::string problem = type == "chlist" ? channelListProblem(value) : contentProblem(type, value);
        if (!problem.empty()) throw fail("attribute '" + name + "': " + problem);
        if (name == "channels" && type == "chlist") chunk.pixelBytes = pixelBytes(value);
        if (name == "dataWindow" && type == "box2i")
          chunk.width = int64_t(littleEndianInt(value, 8)) - int64_t(littleEndianInt(value, 0)) + 1;
        if (name == "compression" && type == "compression") chunk.compression = static_cast<unsigned char>(value[0]);
        if (name == "tiles" && type == "tiledesc")
          chunk.tileWidth = uint32_t(littleEndianInt(value, 0)), chunk.tileHeight = uint32_t(littleEndianInt(value, 4));
      } else {
        in.seekg(bytes, std::ios::cur);
      }
    }
    if (const uint64_t bytes = chunkBytes(chunk); bytes > kMaxChunkBytes)
      throw fail(formatted("declares chunks of %llu bytes (a data window %lld pixels wide), more than the %llu of any image "
                           "glossy reads: OpenEXR would allocate them before reading a pixel",
                           static_cast<unsigned long long>(bytes), static_cast<long long>(chunk.width),
                           static_cast<unsigned long long>(kMaxChunkBytes)));
    // A single-part file has one header; a multipart file's list ends with an empty header.
    if (!(version & kMultipart) || empty) return;
  }
}

}  // namespace glossy
