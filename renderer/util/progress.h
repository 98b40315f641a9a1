// A progress bar with elapsed time and ETA on stderr, drawn only when stderr is a terminal (logs and CI
// stay clean). Safe to advance from many threads; redraws at most ten times a second.
#pragma once

#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace glossy {

class Progress {
 public:
  Progress(std::string label, size_t total);
  ~Progress() { finish(); }
  void advance(size_t n = 1);
  void finish();

 private:
  void draw(size_t done, bool final);

  std::string label_;
  size_t total_;
  std::atomic<size_t> done_{0};
  bool enabled_;
  bool finished_ = false;
  std::mutex drawing_;
  std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace glossy
