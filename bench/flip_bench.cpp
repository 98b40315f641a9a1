// Milliseconds per HDR-ꟻLIP call on a sheet's panels: each analytic panel against the measured one, as a
// sheet computes its error maps (renderer/sheet/error_maps.h), on one thread and on all.
// Usage: flip_bench SHEET.exr [--runs N]
#include "renderer/image/exr_image.h"
#include "renderer/image/flip.h"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <thread>

int main(int argc, char** argv) {
  using namespace glossy;
  std::string sheet;
  int runs = 10;
  CLI::App app{"ms per HDR-FLIP call on a sheet's panels"};
  app.add_option("sheet", sheet, "A sheet EXR (glossy sheet)")->required();
  app.add_option("--runs", runs, "Calls timed per panel")->check(CLI::Range(1, 1000));
  CLI11_PARSE(app, argc, argv);

  const auto crop = [&](const RgbImage& layer, const std::string& name) {
    int x = 0, y = 0, w = 0, h = 0;
    std::istringstream(readImageAttribute(sheet, "glossy:panel." + name + ".box")) >> x >> y >> w >> h;
    RgbImage out(w, h);
    for (int j = 0; j < h; ++j) std::copy_n(layer.at(x, y + j), 3 * w, out.at(0, j));
    return out;
  };
  const RgbImage measured = crop(readImageLayer(sheet, "measured"), "measured");
  std::istringstream panels(readImageAttribute(sheet, "glossy:panels"));
  std::printf("| panel | size | exposures | ms, 1 thread | ms, %u threads |\n|---|---|---|---|---|\n", std::thread::hardware_concurrency());
  for (std::string name; std::getline(panels, name, ',');) {
    if (name == "measured" || readImageAttribute(sheet, "glossy:panel." + name + ".empty") == "1") continue;
    const RgbImage panel = crop(readImageLayer(sheet, name), name);
    const auto time = [&](size_t threads) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      hdrFlip(measured, panel);  // warm
      const auto start = std::chrono::steady_clock::now();
      for (int i = 0; i < runs; ++i) hdrFlip(measured, panel);
      return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count() / runs;
    };
    const double one = time(1), all = time(std::thread::hardware_concurrency());
    std::printf("| %s | %dx%d | %d | %.1f | %.1f |\n", name.c_str(), panel.width, panel.height, hdrFlipExposures(measured).count, one, all);
  }
}
