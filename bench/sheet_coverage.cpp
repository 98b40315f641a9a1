// Whether a sheet's 95 % intervals hold (prints figures, asserts nothing; the sweep test asserts): over
// seeds of one small sheet, each model's noise-free relative RMSE r* and luminance ratio against the value of
// a converged sheet (coverage), and the seed-to-seed σ of the figure against the interval's implied σ
// (half-width / 1.96); for HDR-ꟻLIP, whose interval is the noise's spread at this spp, the same against the
// figure's mean over the seeds. The panels' replicates are cached per seed (--cache), so that a change to
// the estimator (comparison.cpp) is measured again on the same renders without rendering them again.
// COVERAGE_DEBUG_PANEL=k prints analytic panel k's figures seed by seed; the last column counts the seeds
// whose r* interval has fewer than COVERAGE_DOF (default 10) degrees of freedom, and how many of those cover;
// then the seeds whose sheet stands under a warning (figureWarnings: no verdict), and how many of those cover.
// Last, how many seeds name one model closest, and how many of those name another than the converged sheet.
#include "materials/merl/merl_table.h"
#include "materials/nbrdf/neural_brdf.h"
#include "renderer/sheet/sheet.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

using namespace glossy;

namespace {

// One seed's render: every panel's replicates (measured first), the mask, and each analytic panel's ꟻLIP.
struct Render {
  std::vector<std::vector<RgbImage>> panels;  // [0]: measured
  std::vector<char> mask;
  std::vector<double> flip, flipLo, flipHi;   // per analytic panel
};

template <class T> void put(std::ofstream& o, const std::vector<T>& v) {
  const uint64_t n = v.size();
  o.write(reinterpret_cast<const char*>(&n), sizeof n);
  o.write(reinterpret_cast<const char*>(v.data()), std::streamsize(n * sizeof(T)));
}
template <class T> void get(std::ifstream& i, std::vector<T>& v) {
  uint64_t n = 0;
  i.read(reinterpret_cast<char*>(&n), sizeof n);
  v.resize(n);
  i.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(T)));
}

Render fromSheet(const Sheet& sheet) {
  Render r;
  r.mask = sheet.objectMask;
  r.panels.push_back(sheet.measured()->replicates);
  for (const PanelRender& p : sheet.panels) {
    if (p.panel.fit.empty()) continue;
    r.panels.push_back(p.replicates);
    r.flip.push_back(p.maps.available ? p.maps.flip : -1.0);
    r.flipLo.push_back(p.maps.hasCi ? p.maps.flipCi.lo : -1.0);
    r.flipHi.push_back(p.maps.hasCi ? p.maps.flipCi.hi : -1.0);
  }
  return r;
}

void save(const Render& r, const std::filesystem::path& path) {
  std::ofstream o(path.string() + ".tmp", std::ios::binary);
  const uint64_t panels = r.panels.size(), k = r.panels.front().size();
  o.write(reinterpret_cast<const char*>(&panels), sizeof panels);
  o.write(reinterpret_cast<const char*>(&k), sizeof k);
  for (const auto& p : r.panels)
    for (const RgbImage& image : p) put(o, image.pixels);
  put(o, r.mask), put(o, r.flip), put(o, r.flipLo), put(o, r.flipHi);
  o.close();
  std::filesystem::rename(path.string() + ".tmp", path);
}

Render load(const std::filesystem::path& path, int size) {
  std::ifstream i(path, std::ios::binary);
  uint64_t panels = 0, k = 0;
  i.read(reinterpret_cast<char*>(&panels), sizeof panels);
  i.read(reinterpret_cast<char*>(&k), sizeof k);
  Render r;
  r.panels.assign(panels, std::vector<RgbImage>(k, RgbImage(size, size)));
  for (auto& p : r.panels)
    for (RgbImage& image : p) get(i, image.pixels);
  get(i, r.mask), get(i, r.flip), get(i, r.flipLo), get(i, r.flipHi);
  return r;
}

Comparison compare(const Render& r) {
  std::vector<std::vector<RgbImage>> analytic(r.panels.begin() + 1, r.panels.end());
  return compareToMeasured(analytic, r.panels.front(), r.mask);
}

struct Moments {
  double n = 0, sum = 0, sum2 = 0;
  void add(double x) { n += 1, sum += x, sum2 += x * x; }
  double mean() const { return sum / n; }
  double sd() const { return std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))); }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sheet_coverage: whether a sheet's intervals hold over seeds"};
  std::string material = "blue-acrylic", merlDir = std::string(GLOSSY_SHARED_DIR) + "/merl", cache = "/tmp/sheet-coverage";
  int size = 64, spp = 64, seeds = 40, convergedSpp = 4096, threads = 0;
  app.add_option("--material", material, "Material of the library")->capture_default_str();
  app.add_option("--merl-dir", merlDir, "Folder with its MERL table")->capture_default_str();
  app.add_option("--size", size, "Panel width and height")->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel of the seeds' sheets")->capture_default_str();
  app.add_option("--seeds", seeds, "Seeds 1..N")->capture_default_str();
  app.add_option("--converged-spp", convergedSpp, "Samples per pixel of the converged sheet (seed 1000)")->capture_default_str();
  app.add_option("--threads", threads, "Threads (0 = all cores)")->capture_default_str();
  app.add_option("--cache", cache, "Folder of cached renders")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const std::filesystem::path source(GLOSSY_SOURCE_DIR);
  const SceneDescription description = loadGltf(source / "scenes/preview.gltf");
  const EmbreeScene bvh(description);
  const Environment environment = Environment::makeDefault();
  const SheetScene scene = makeSheetScene(description, bvh, environment, description.cameras.front());
  const MaterialFile m = loadMaterialFile(source / "materials/library/merl" / (material + ".toml"));
  const auto table = resolveMeasured(m.measured, merlDir, m.path.parent_path());
  if (!table) {
    std::fprintf(stderr, "sheet_coverage: no %s in %s\n", m.measured.c_str(), merlDir.c_str());
    return 2;
  }
  const auto measured = std::make_shared<const MerlTable>(
      table->extension() == ".nbrdf" ? NeuralBrdf::load(*table).tabulate() : MerlTable::load(*table));
  std::filesystem::create_directories(cache);
  double renderSeconds = 0.0;
  const auto get = [&](int sampleCount, uint32_t seed) {
    const std::filesystem::path path =
        std::filesystem::path(cache) / (material + "-" + std::to_string(size) + "-" + std::to_string(sampleCount) + "-" +
                                        std::to_string(seed) + ".bin");
    if (std::filesystem::exists(path)) return load(path, size);
    SheetSettings s;
    s.width = s.height = size;
    s.spp = sampleCount;
    s.seed = seed;
    s.threads = threads;
    s.progress = false;
    const auto start = std::chrono::steady_clock::now();
    const Render r = fromSheet(renderSheet(scene, m, measured, "", s));
    renderSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    save(r, path);
    return r;
  };

  const Comparison converged = compare(get(convergedSpp, 1000));
  const Verdict convergedVerdict = verdictUnderWarnings(converged.verdict, figureWarnings(converged.panels));
  int named = 0, wrong = 0;
  const size_t n = converged.panels.size();
  std::vector<Moments> r(n), rSigma(n), l(n), lSigma(n), f(n), fSigma(n);
  std::vector<int> rCover(n), lCover(n), fewDof(n), fewDofCovered(n), warned(n), warnedCovered(n);
  const double dofWarning = std::getenv("COVERAGE_DOF") ? std::atof(std::getenv("COVERAGE_DOF")) : 10.0;
  std::vector<std::vector<double>> flips(n), flipLo(n), flipHi(n);
  for (int seed = 1; seed <= seeds; ++seed) {
    const Render render = get(spp, uint32_t(seed));
    const Comparison c = compare(render);
    const std::vector<std::string> warnings = figureWarnings(c.panels);
    const bool warning = !warnings.empty();
    if (const Verdict v = verdictUnderWarnings(c.verdict, warnings); v.models.size() == 1)
      ++named, wrong += convergedVerdict.models.size() == 1 && v.models.front() != convergedVerdict.models.front();
    if (const char* d = std::getenv("COVERAGE_DEBUG_PANEL")) {
      const PanelFigures& x = c.panels[size_t(std::atoi(d))];
      std::printf("seed %d: r* %.4f [%.4f, %.4f] noisy %.4f dof %.1f\n", seed, x.relativeRmse, x.relativeRmseCi.lo, x.relativeRmseCi.hi,
                  x.noisyRelativeRmse, x.relativeRmseDof);
    }
    for (size_t p = 0; p < n; ++p) {
      const PanelFigures& x = c.panels[p];
      const PanelFigures& y = converged.panels[p];
      if (!x.hasCi) continue;
      r[p].add(x.relativeRmse), rSigma[p].add(x.relativeRmseCi.halfWidth() / 1.96);
      l[p].add(x.luminanceRatio), lSigma[p].add(x.luminanceRatioCi.halfWidth() / 1.96);
      const bool covered = x.relativeRmseCi.lo <= y.relativeRmse && y.relativeRmse <= x.relativeRmseCi.hi;
      rCover[p] += covered;
      if (x.relativeRmseDof < dofWarning) ++fewDof[p], fewDofCovered[p] += covered;
      if (warning) ++warned[p], warnedCovered[p] += covered;
      lCover[p] += x.luminanceRatioCi.lo <= y.luminanceRatio && y.luminanceRatio <= x.luminanceRatioCi.hi;
      if (render.flipLo[p] >= 0.0) {
        f[p].add(render.flip[p]), fSigma[p].add((render.flipHi[p] - render.flipLo[p]) / 2.0 / 1.96);
        flips[p].push_back(render.flip[p]), flipLo[p].push_back(render.flipLo[p]), flipHi[p].push_back(render.flipHi[p]);
      }
    }
  }
  std::printf("%s %d² %d spp, %d seeds, converged %d spp (render %.0f s)\n", material.c_str(), size, spp, seeds, convergedSpp,
              renderSeconds);
  std::printf("%-3s %-8s %-8s %-8s %-6s %-5s | %-7s %-6s %-5s | %-7s %-6s %-5s | %s\n", "p", "r*conv", "r*mean", "r*sd", "ratio",
              "cov", "lumconv", "ratio", "cov", "flip", "ratio", "cov", "seeds with dof < limit (covered) | warned (covered)");
  for (size_t p = 0; p < n; ++p) {
    if (!r[p].n) continue;
    int fCover = 0;
    const double fMean = f[p].n ? f[p].mean() : 0.0;
    for (size_t s = 0; s < flips[p].size(); ++s) fCover += flipLo[p][s] <= fMean && fMean <= flipHi[p][s];
    // The implied σ: the root mean square of the seeds' (what an average interval says).
    const auto implied = [](const Moments& m) { return std::sqrt(m.sum2 / m.n); };
    std::printf("%-3zu %-8.4f %-8.4f %-8.5f %-6.2f %-5.0f | %-7.4f %-6.2f %-5.0f | %-7.4f %-6.2f %-5.0f | %d (%d) | %d (%d)\n", p,
                converged.panels[p].relativeRmse, r[p].mean(), r[p].sd(), r[p].sd() / implied(rSigma[p]), 100.0 * rCover[p] / r[p].n,
                converged.panels[p].luminanceRatio, l[p].sd() / implied(lSigma[p]), 100.0 * lCover[p] / l[p].n, fMean,
                f[p].n ? f[p].sd() / implied(fSigma[p]) : 0.0, f[p].n ? 100.0 * fCover / f[p].n : 0.0, fewDof[p], fewDofCovered[p], warned[p], warnedCovered[p]);
  }
  std::printf("verdicts naming one model: %d of %d seeds, %d of them not the converged sheet's (%s)\n", named, seeds, wrong,
              convergedVerdict.why.c_str());
  return 0;
}
