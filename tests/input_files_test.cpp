// Input files that are not what their names say: a device (a path symlinked to /dev/zero, which readers
// would otherwise read until memory or time runs out), a FIFO, a file far larger than any such input, and
// an environment map whose header asks for more memory than the machine has. Each is bad input: exit 2
// and one line naming the file, before anything is rendered.
#include "materials/core/input_file.h"
#include "materials/merl/merl_table.h"
#include "materials/nbrdf/neural_brdf.h"
#include "renderer/image/exr_image.h"
#include "renderer/lights/environment.h"
#include "renderer/scene/scene.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <condition_variable>
#include <fcntl.h>
#include <mutex>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

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
          {"eval", "--measured", file(".binary")},
          {"sample", "--measured", file(".nbrdf"), "--wo", "0,0,1", "-n", "1"},
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

namespace {

// Lets a reader that blocked opening `fifo` go, after a few seconds, by opening the FIFO's other end (again
// and again, for a reader that retries): a reader that waits on a FIFO then fails the test rather than
// hang it. fired() says whether it had to.
class FifoUnblocker {
 public:
  explicit FifoUnblocker(std::filesystem::path fifo)
      : thread_([this, fifo] {
          std::unique_lock lock(mutex_);
          if (cv_.wait_for(lock, std::chrono::seconds(5), [this] { return done_; })) return;
          fired_ = true;
          while (!cv_.wait_for(lock, std::chrono::milliseconds(20), [this] { return done_; }))
            if (const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK); fd >= 0) ::close(fd);
        }) {}
  ~FifoUnblocker() { stop(); }
  bool stop() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    cv_.notify_all();
    if (thread_.joinable()) thread_.join();
    return fired_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool done_ = false, fired_ = false;
  std::thread thread_;
};

}  // namespace

// The readers behind every command and the Python module (glossy.read_exr is readRgbImage): each refuses a
// FIFO as bad input naming it, without opening it in a way that waits for a writer.
TEST(InputFiles, EveryReaderRefusesAFifoAtOnce) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  for (const char* name : {"a.exr", "a.hdr", "a.binary", "a.binary.xz", "a.nbrdf", "a.gltf", "a.png"})
    std::filesystem::create_symlink(dir / "pipe", dir / name);
  const std::vector<std::pair<std::string, std::function<void()>>> readers = {
      {"readRgbImage", [&] { readRgbImage(dir / "a.exr"); }},
      {"readImageLayer", [&] { readImageLayer(dir / "a.exr", "measured"); }},
      {"readImageAttribute", [&] { readImageAttribute(dir / "a.exr", "glossy:settings"); }},
      {"readRgbImage png", [&] { readRgbImage(dir / "a.png"); }},
      {"Environment::load", [&] { Environment::load(dir / "a.hdr"); }},
      {"MerlTable::load", [&] { MerlTable::load(dir / "a.binary"); }},
      {"MerlTable::load xz", [&] { MerlTable::load(dir / "a.binary.xz"); }},
      {"NeuralBrdf::load", [&] { NeuralBrdf::load(dir / "a.nbrdf"); }},
      {"loadGltf", [&] { loadGltf(dir / "a.gltf"); }},
      {"requireInputFile", [&] { requireInputFile(dir / "a.exr", "image"); }},
  };
  for (const auto& [what, read] : readers) {
    SCOPED_TRACE(what);
    FifoUnblocker unblocker(dir / "pipe");
    const std::string e = expectInputError(read);
    EXPECT_FALSE(unblocker.stop()) << "waited on the FIFO";
    EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
  }
}

// The files a glTF scene names are inputs too: a buffer that is a FIFO is refused naming it.
TEST(InputFiles, AGltfBufferThatIsAFifoIsRefused) {
  TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "mesh.bin").c_str(), 0600), 0);
  writeText(dir / "scene.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "mesh.bin", "byteLength": 36}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}]})");
  FifoUnblocker unblocker(dir / "mesh.bin");
  const std::string e = expectInputError([&] { loadGltf(dir / "scene.gltf"); });
  EXPECT_FALSE(unblocker.stop()) << "waited on the FIFO";
  EXPECT_NE(e.find("mesh.bin"), std::string::npos) << e;
  EXPECT_NE(e.find("is a FIFO"), std::string::npos) << e;
}

}  // namespace glossy::test
