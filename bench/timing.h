// Timing for the benchmarks: the wall-clock seconds of a call, and medians of them.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace glossy::bench {

template <class F>
double seconds(F&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The median of `runs` timed calls of f.
template <class F>
double medianSeconds(int runs, F&& f) {
  std::vector<double> t;
  for (int i = 0; i < runs; ++i) t.push_back(seconds(f));
  return median(std::move(t));
}

}  // namespace glossy::bench
