// What a sheet spends on its measured data before it renders (prints figures, asserts nothing): for each
// given file, the steps of renderer/app/sheet_job.cpp and renderer/sheet/sheet.cpp that read it — loading
// it as loadMeasured does (a .nbrdf is tabulated, a .binary.xz decompressed), the measured panel's BRDF with
// its tabulated sampler, and the E1 and E2 data the fits' BRDF errors are taken against — each in CPU
// seconds (all threads) and wall seconds, then the median and maximum of the totals over the files.
//   build/bench/measured_load --threads 1 materials/library/*/*.nbrdf ../shared/merl/chrome.binary.xz
#include "materials/core/lane_math.h"
#include "renderer/util/notes.h"
#include "materials/fitting/metric.h"
#include "materials/models/measured.h"
#include "renderer/app/brdf_options.h"

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <optional>

using namespace glossy;

namespace {

struct Cost {
  double cpu = 0.0, wall = 0.0;
  Cost& operator+=(const Cost& o) {
    cpu += o.cpu, wall += o.wall;
    return *this;
  }
};

double cpuSeconds() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <class F>
Cost cost(F&& f) {
  const double cpu = cpuSeconds();
  const auto wall = std::chrono::steady_clock::now();
  f();
  return {cpuSeconds() - cpu, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count()};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"measured_load: CPU and wall seconds a sheet spends loading each measured file"};
  std::vector<std::string> files;
  int threads = 0;
  bool sse2 = false;
  app.add_option("files", files, "Measured files (.nbrdf, .binary, .binary.xz)")->required()->check(CLI::ExistingFile);
  app.add_option("--threads", threads, "Threads (0 = all cores)")->capture_default_str();
  app.add_flag("--sse2", sse2, "Baseline x86-64 code only, as on a CPU without AVX2 (lane_math.h)");
  CLI11_PARSE(app, argc, argv);
  if (sse2) lanes::setIsa(lanes::Isa::Sse2);
  std::optional<tbb::global_control> limit;
  if (threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, size_t(threads));

  std::printf("%-60s %15s %15s %15s %15s\n", "file", "load cpu/wall", "sampler", "E1+E2 data", "total");
  std::vector<double> cpu, wall;
  for (const std::string& file : files) {
    std::shared_ptr<const MerlTable> table;
    std::optional<Measured> measured;
    std::optional<MetricData> e1, e2;
    const Cost load = cost([&] { table = app::loadMeasured(file); });
    discardNotes();  // the unmeasured bins' note
    const Cost sampler = cost([&] { measured.emplace(table); });
    const Cost metric = cost([&] { e1.emplace(*table, Metric::E1), e2.emplace(*table, Metric::E2); });
    Cost total = load;
    total += sampler;
    total += metric;
    std::printf("%-60s %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f\n", file.c_str(), load.cpu, load.wall, sampler.cpu,
                sampler.wall, metric.cpu, metric.wall, total.cpu, total.wall);
    std::fflush(stdout);
    cpu.push_back(total.cpu), wall.push_back(total.wall);
  }
  std::printf("%zu files, %d threads: total CPU s median %.3f max %.3f; wall s median %.3f max %.3f\n", files.size(),
              threads, median(cpu), *std::max_element(cpu.begin(), cpu.end()), median(wall),
              *std::max_element(wall.begin(), wall.end()));
}
