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

TEST(ExrPreflight, AFileOpenImageIoWroteIsAccepted) {
  TempDir tmp;
  RgbImage image(4, 3);
  writeExr(tmp / "a.exr", image, {});
  EXPECT_EQ(refusal(tmp / "a.exr"), "");
}

}  // namespace glossy::test
