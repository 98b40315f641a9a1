#include "tests/support/test_support.h"

#include "materials/core/input_error.h"
#include "materials/params/importer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace glossy::test {

std::filesystem::path sharedDir() {
  if (const char* env = std::getenv("GLOSSY_SHARED_DIR"); env && *env) return env;
  return GLOSSY_SHARED_DIR;
}
std::filesystem::path sourceDir() { return GLOSSY_SOURCE_DIR; }
std::filesystem::path libraryDir() { return sourceDir() / "materials/library"; }
std::filesystem::path materialsDir() { return libraryDir() / "merl"; }

const std::vector<std::string>& supplementMaterials() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(materialsDir()))
      if (e.path().extension() == ".toml" && loadMaterialFile(e.path()).source == kSupplementSource) out.push_back(e.path().stem().string());
    std::sort(out.begin(), out.end());
    if (out.size() != 6) throw std::runtime_error(materialsDir().string() + ": " + std::to_string(out.size()) + " supplement materials, not 6");
    return out;
  }();
  return names;
}

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) {
    if (c == '\'')
      q.append("'\\''");
    else
      q.push_back(c);
  }
  return q + "'";
}

namespace {

RunResult run(const std::string& prefix, const std::vector<std::string>& args, const std::string& input) {
  TempDir tmp;
  writeText(tmp / "stdin", input);
  // A test run inside a job array must not shard itself by the array's variables (renderer/app/shard.h).
  std::string cmd = prefix + "env -u SLURM_ARRAY_TASK_ID -u JOB_COMPLETION_INDEX -u AWS_BATCH_JOB_ARRAY_INDEX " + shellQuote(GLOSSY_EXE);
  for (const auto& a : args) cmd.append(" ").append(shellQuote(a));
  cmd.append(" <").append(shellQuote((tmp / "stdin").string()));
  cmd.append(" >").append(shellQuote((tmp / "stdout").string()));
  cmd.append(" 2>").append(shellQuote((tmp / "stderr").string()));
  RunResult r;
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = readText(tmp / "stdout");
  r.err = readText(tmp / "stderr");
  // Under scripts/test --sanitize the glossy process is instrumented too: its report fails the test that
  // ran it, whatever exit status the test expects, and is shown whole.
  for (const char* mark : {"ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error: "}) {
    if (r.err.find(mark) != std::string::npos) {
      ADD_FAILURE() << "sanitizer report from glossy:\n" << r.err;
      break;
    }
  }
  return r;
}

}  // namespace

RunResult runGlossy(const std::vector<std::string>& args, const std::string& input) { return run("", args, input); }

RunResult runGlossyIn(const std::filesystem::path& cwd, const std::vector<std::string>& unset, const std::vector<std::string>& args) {
  std::string prefix = "cd " + shellQuote(cwd.string()) + " && env";
  for (const std::string& name : unset) prefix += " -u " + shellQuote(name);
  return run(prefix + " ", args, "");
}

std::string expectInputError(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "not one line: " << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return {};
}

void expectOneLineError(const RunResult& r, const std::string& mention) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  ASSERT_FALSE(r.err.empty());
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "not one line: " << r.err;
  // One safe line (materials/core/text.h, safeLine): no control character a terminal would act on.
  const bool control = std::any_of(r.err.begin(), r.err.end() - 1, [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; });
  EXPECT_FALSE(control) << "a control character in: " << r.err;
  EXPECT_NE(r.err.find(mention), std::string::npos) << r.err;
}

TempDir::TempDir() {
  std::string tmpl = (std::filesystem::temp_directory_path() / "glossy-test-XXXXXX").string();
  if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
  path_ = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::map<std::string, std::string>> readCsv(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  // RFC 4180 fields on one line: a quoted field may hold commas, and "" in it is one quote.
  auto split = [](const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (size_t i = 0; i < line.size(); ++i) {
      const char c = line[i];
      if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"')
        cells.back() += '"', ++i;
      else if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        cells.emplace_back();
      else
        cells.back() += c;
    }
    return cells;
  };
  std::string line;
  std::getline(in, line);
  const auto header = split(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto cells = split(line);
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

std::string syntheticMerlBytes(const MerlFiller& f) {
  constexpr int nh = 90, nd = 90, np = 180;
  constexpr size_t bins = size_t(nh) * nd * np;
  std::string bytes(12 + 3 * bins * 8, '\0');
  const int32_t dims[3] = {nh, nd, np};
  std::memcpy(bytes.data(), dims, sizeof dims);
  for (int h = 0; h < nh; ++h)
    for (int d = 0; d < nd; ++d)
      for (int p = 0; p < np; ++p) {
        const Rgb v = f(h, d, p);
        const size_t idx = size_t(p) + np * (size_t(d) + nd * size_t(h));
        for (int c = 0; c < 3; ++c) {
          const double x = v[c];
          std::memcpy(bytes.data() + 12 + (c * bins + idx) * 8, &x, 8);
        }
      }
  return bytes;
}

std::string tabulatedMerlBytes(const Brdf& brdf, const BinPredicate& unmeasured) {
  return syntheticMerlBytes([&](int h, int d, int p) {
    if (unmeasured && unmeasured(h, d, p)) return Rgb(-1.0);
    const double fh = (h + 0.5) / 90.0;
    const auto [L, V] = fromHalfDiff(fh * fh * kPi / 2, (d + 0.5) / 90.0 * kPi / 2, (p + 0.5) / 180.0 * kPi);
    const Rgb rho = eval(brdf, L, V);
    return Rgb(rho.r / MerlTable::kScale[0], rho.g / MerlTable::kScale[1], rho.b / MerlTable::kScale[2]);
  });
}

Fit makeFit(const std::string& model, const std::string& metric,
            const std::vector<std::pair<std::string, ParamSet::Value>>& values) {
  Fit f;
  f.id = {model, metric};
  for (const auto& [k, v] : values) f.params.set(k, v);
  validateFit(f, "round trip " + f.id.str());
  return f;
}

double lobeWidth(const Fit& f) {
  if (f.id.model == "cook-torrance") return f.params.scalar("m");
  if (f.id.model == "ggx" || f.id.model == "ward" || f.id.model == "ward-duer") return f.params.scalar("alpha");
  if (f.id.model == "ngan-cook-torrance") return f.params.scalar("m");
  if (f.id.model == "ashikhmin-shirley" || f.id.model == "blinn-phong" || f.id.model == "ngan-ashikhmin-shirley")
    return 1.0 / std::sqrt(f.params.scalar("n"));
  return std::sqrt(std::expm1(std::log(2.0) / f.params.scalar("c")) / f.params.scalar("b"));
}

std::shared_ptr<const MerlTable> tabulateMerl(const Brdf& brdf, const BinPredicate& unmeasured) {
  const std::string bytes = tabulatedMerlBytes(brdf, unmeasured);
  return std::make_shared<const MerlTable>(
      MerlTable::parse({reinterpret_cast<const std::byte*>(bytes.data()), bytes.size()}, "synthetic"));
}

std::pair<Vec3, Vec3> fromHalfDiff(double thetaH, double thetaD, double phiD, double phiH) {
  // D in the half-vector frame, then rotate about y by θ_h and about z by φ_h (the inverse of the
  // MERL reference's to-half/diff rotation); V is the reflection of L about H.
  const Vec3 d(std::sin(thetaD) * std::cos(phiD), std::sin(thetaD) * std::sin(phiD), std::cos(thetaD));
  const double ct = std::cos(thetaH), st = std::sin(thetaH);
  const Vec3 l1(d.x * ct + d.z * st, d.y, -d.x * st + d.z * ct);
  const double cp = std::cos(phiH), sp = std::sin(phiH);
  const Vec3 L(l1.x * cp - l1.y * sp, l1.x * sp + l1.y * cp, l1.z);
  const Vec3 H(st * cp, st * sp, ct);
  const double hl = L.x * H.x + L.y * H.y + L.z * H.z;
  const Vec3 V = 2.0 * hl * H - L;
  return {L, V};
}

std::vector<std::string> htmlReferences(const std::string& html) {
  std::vector<std::string> refs;
  static const std::regex ref(R"([ ](?:src|href|data-src|data-measured-src)="([^"]*)\")");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), ref); it != std::sregex_iterator(); ++it) refs.push_back((*it)[1]);
  return refs;
}

}  // namespace glossy::test
