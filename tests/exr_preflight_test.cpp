// The OpenEXR header check (renderer/image/exr_preflight.h): headers whose sizes would make OpenEXR read
// from another place than their claims say, or allocate from sizes inside an attribute, are refused before
// OpenEXR sees them; a real file passes.
#include "materials/core/input_error.h"
#include "renderer/image/exr_image.h"
#include "renderer/image/exr_preflight.h"
#include "tests/support/test_support.h"

#include <cstdint>
#include <fstream>
#include <string>

namespace glossy::test {

namespace {

// An OpenEXR header: the magic number and version 2, the attributes given, the empty name that ends them.
struct Header {
  std::string bytes = std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);

  static std::string int32(int32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); }
  Header& attribute(const std::string& name, const std::string& type, const std::string& value) {
    return attribute(name, type, int32_t(value.size()), value);
  }
  Header& attribute(const std::string& name, const std::string& type, int32_t claimed, const std::string& value) {
    bytes += name + '\0' + type + '\0' + int32(claimed) + value;
    return *this;
  }
  std::filesystem::path write(const TempDir& dir) const {
    const std::filesystem::path path = dir / "h.exr";
    // The end of the header, then room for what follows a header in a real file.
    std::ofstream(path, std::ios::binary) << bytes << '\0' << std::string(4096, '\0');
    return path;
  }
};

std::string refusal(const std::filesystem::path& path) {
  try {
    preflightExr(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExrPreflight, AFixedSizeAttributeClaimingAnotherSizeIsRefused) {
  TempDir tmp;
  // OpenEXR reads a box2i's 16 bytes whatever the claim: with a claim of 0 it goes on 16 bytes further than
  // the claims say, into bytes an attacker chose to look like a string of 2 GB.
  const std::string message = refusal(Header().attribute("dataWindow", "box2i", 0, std::string(16, '\0')).write(tmp));
  EXPECT_NE(message.find("'dataWindow' of type box2i claims 0 bytes, not its 16"), std::string::npos) << message;
  EXPECT_EQ(refusal(Header().attribute("dataWindow", "box2i", std::string(16, '\0')).write(tmp)), "");
}

TEST(ExrPreflight, AStringVectorsStringsMustFitInIt) {
  TempDir tmp;
  const std::string message =
      refusal(Header().attribute("names", "stringvector", Header::int32(2000000000) + "ab").write(tmp));
  EXPECT_NE(message.find("string of 2000000000 bytes"), std::string::npos) << message;
  EXPECT_EQ(refusal(Header().attribute("names", "stringvector", Header::int32(2) + "ab" + Header::int32(0)).write(tmp)), "");
}

TEST(ExrPreflight, APreviewImageMustBeTheSizeItSays) {
  TempDir tmp;
  const std::string pixels(4 * 2 * 2, '\x7f');
  const std::string message =
      refusal(Header().attribute("preview", "preview", Header::int32(65536) + Header::int32(65536) + pixels).write(tmp));
  EXPECT_NE(message.find("65536 x 65536 pixels"), std::string::npos) << message;
  EXPECT_EQ(refusal(Header().attribute("preview", "preview", Header::int32(2) + Header::int32(2) + pixels).write(tmp)), "");
}

// A header of a few bytes that declares a data window 2^28 pixels wide: OpenEXR would allocate its 16-line
// chunks' buffers (48 GiB of float RGB) on opening it. A window 4096 wide is what images are.
TEST(ExrPreflight, ChunksLargerThanAnyImageAreRefusedBeforeOpenExrAllocatesThem) {
  TempDir tmp;
  std::string channels;
  for (const char* c : {"B", "G", "R"}) channels += std::string(c) + '\0' + Header::int32(2) + std::string(4, '\0') + Header::int32(1) + Header::int32(1);
  channels += '\0';
  const auto header = [&](int32_t width, char compression) {
    return Header()
        .attribute("channels", "chlist", channels)
        .attribute("compression", "compression", std::string(1, compression))
        .attribute("dataWindow", "box2i", Header::int32(0) + Header::int32(0) + Header::int32(width - 1) + Header::int32(0));
  };
  const std::string message = refusal(header(1 << 28, 3).write(tmp));
  EXPECT_NE(message.find("declares chunks of 51539607552 bytes (a data window 268435456 pixels wide)"), std::string::npos) << message;
  EXPECT_EQ(refusal(header(4096, 3).write(tmp)), "");
  // DWAB decodes 256 lines at once: 2^20 columns of float RGB is 3 GiB a chunk.
  EXPECT_NE(refusal(header(1 << 20, 9).write(tmp)), "");
  EXPECT_EQ(refusal(header(1 << 20, 0).write(tmp)), "");  // one line at a time: 12 MiB
}

TEST(ExrPreflight, AFileOpenImageIoWroteIsAccepted) {
  TempDir tmp;
  RgbImage image(4, 3);
  writeExr(tmp / "a.exr", image, {});
  EXPECT_EQ(refusal(tmp / "a.exr"), "");
}

}  // namespace glossy::test
