// What a random load costs on this machine, for reading the profiles in docs/performance.md: the
// latency of one dependent chain of loads through tables of growing size (where it jumps is the cache
// this process really gets), and the time per load with several independent chains in flight at once
// (where it stops falling is how many cache misses the core overlaps). Tables are 2 MiB-aligned and
// offered as huge pages, like the environment's, so TLB misses do not count. Prints; asserts nothing.
// Usage: memory_latency [--loads N]
#include "materials/sampling/huge_pages.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

namespace {

struct Line {
  uint64_t next;  // index of the next line of the chain
  uint64_t pad[7];
};
static_assert(sizeof(Line) == 64);

// A table of `lines` cache lines, each pointing to the next of one random cycle through all of them.
glossy::HugePageVector<Line> randomCycle(std::size_t lines) {
  glossy::HugePageVector<Line> table(lines);
  std::vector<uint64_t> order(lines);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
  for (std::size_t i = 0; i < lines; ++i) table[order[i]].next = order[(i + 1) % lines];
  return table;
}

// ns per load for `chains` independent chains stepped in turn, `loads` loads in all.
double nsPerLoad(const glossy::HugePageVector<Line>& table, int chains, std::size_t loads) {
  std::vector<uint64_t> at(static_cast<std::size_t>(chains));
  for (int c = 0; c < chains; ++c) at[std::size_t(c)] = uint64_t(c) * (table.size() / std::size_t(chains));
  for (std::size_t i = 0; i < table.size(); ++i) at[0] = table[at[0]].next;  // warm-up: one lap
  const std::size_t steps = std::max<std::size_t>(1, loads / std::size_t(chains));
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t s = 0; s < steps; ++s)
    for (int c = 0; c < chains; ++c) at[std::size_t(c)] = table[at[std::size_t(c)]].next;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  uint64_t sink = 0;
  for (uint64_t a : at) sink += a;
  if (sink == ~uint64_t(0)) std::puts("");  // keeps the chains live
  return seconds * 1e9 / double(steps * std::size_t(chains));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Latency of random loads by table size, and time per load with independent misses in flight"};
  std::size_t loads = 2000000;
  app.add_option("--loads", loads, "loads per measurement")->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  std::printf("one chain of dependent random loads (latency):\n");
  for (double mib : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0, 16.0, 64.0}) {
    const auto table = randomCycle(std::size_t(mib * (1 << 20)) / sizeof(Line));
    std::printf("  %6.2f MiB table: %6.1f ns per load\n", mib, nsPerLoad(table, 1, loads));
  }
  std::printf("independent chains through a 64 MiB table (misses in flight):\n");
  const auto table = randomCycle(std::size_t(64) << 20 >> 6);
  for (int chains : {1, 2, 4, 8, 12, 16, 24, 32, 64})
    std::printf("  %2d chains: %6.1f ns per load\n", chains, nsPerLoad(table, chains, loads));
  return 0;
}
