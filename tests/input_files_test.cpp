// Input files that are not what their names say: a device (a path symlinked to /dev/zero, which readers
// would otherwise read until memory or time runs out), a FIFO, a file far larger than any such input, and
// an environment map whose header asks for more memory than the machine has. Each is bad input: exit 2
// and one line naming the file, before anything is rendered.
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

namespace glossy::test {

namespace {

std::vector<std::vector<std::string>> commandsReading(const std::filesystem::path& dir, const std::string& stem) {
  const auto file = [&](const char* extension) { return (dir / (stem + extension)).string(); };
  const std::string out = (dir / "out.exr").string();
  const std::vector<std::string> tiny = {"--width", "8", "--height", "8", "--spp", "1"};
  auto render = [&](std::vector<std::string> a) {
    a.insert(a.begin(), "render");
    a.insert(a.end(), tiny.begin(), tiny.end());
    a.insert(a.end(), {"-o", out});
    return a;
  };
  return {{"sheet", "--material", file(".toml"), "-o", out},
          {"sheets", file(".toml"), "-o", (dir / "sheets").string()},
          {"import", file(".txt"), "-o", (dir / "imported").string()},
          render({"--measured", file(".nbrdf")}),
          render({"--measured", file(".binary")}),
          render({"--measured", file(".binary.xz")}),
          render({"--env", file(".hdr")}),
          render({"--env", file(".exr")}),
          render({"--scene", file(".gltf")}),
          render({"--scene", file(".glb")})};
}

void linkAll(const std::filesystem::path& dir, const std::string& stem, const std::filesystem::path& target) {
  for (const char* e : {".toml", ".txt", ".nbrdf", ".binary", ".binary.xz", ".hdr", ".exr", ".gltf", ".glb"})
    std::filesystem::create_symlink(target, dir / (stem + e));
}

}  // namespace

TEST(InputFiles, ADeviceBehindAnyInputNameIsRefusedNamingIt) {
  TempDir dir;
  linkAll(dir.path(), "zero", "/dev/zero");
  for (const auto& args : commandsReading(dir.path(), "zero")) {
    SCOPED_TRACE(args[0] + " " + args[1] + " " + args[2]);
    expectOneLineError(runGlossy(args), "zero.");
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(InputFiles, AFifoIsRefusedWithoutWaitingForAWriter) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  linkAll(dir.path(), "fifo", dir / "pipe");
  // Opening a FIFO for reading blocks until someone writes: a reader that opened it first would hang here.
  for (const auto& args : commandsReading(dir.path(), "fifo")) {
    SCOPED_TRACE(args[0] + " " + args[1] + " " + args[2]);
    expectOneLineError(runGlossy(args), "fifo.");
  }
}

TEST(InputFiles, FilesFarLargerThanTheirKindAreRefusedWithTheirSize) {
  TempDir dir;
  const std::string comment(2 << 20, '#');  // a 2 MB comment: no material file is that long
  writeText(dir / "long.toml", comment + "\nname = \"long\"\n");
  const RunResult r = runGlossy({"sheet", "--material", (dir / "long.toml").string(), "-o", (dir / "o.exr").string()});
  expectOneLineError(r, "long.toml");
  EXPECT_NE(r.err.find("too large"), std::string::npos) << r.err;
}

TEST(InputFiles, AnEnvironmentMapLargerThanMemoryIsRefusedBeforeAllocating) {
  TempDir dir;
  // A valid Radiance header asking for 400000 x 200000 texels (1.6 TB to sample), and no pixels.
  writeText(dir / "huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 200000 +X 400000\n");
  const RunResult r = runGlossy({"render", "--env", (dir / "huge.hdr").string(), "--width", "8", "--height", "8", "--spp",
                                 "1", "-o", (dir / "o.exr").string()});
  expectOneLineError(r, "huge.hdr");
  EXPECT_NE(r.err.find("400000x200000"), std::string::npos) << r.err;
}

}  // namespace glossy::test
