#include "renderer/util/progress.h"

#include <cstdio>
#include <unistd.h>

namespace glossy {

Progress::Progress(std::string label, size_t total)
    : label_(std::move(label)), total_(total ? total : 1), enabled_(isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

void Progress::advance(size_t n) {
  const size_t done = done_.fetch_add(n) + n;
  if (!enabled_) return;
  std::unique_lock lock(drawing_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // someone else is drawing; never make a worker wait
  const auto now = std::chrono::steady_clock::now();
  if (now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  draw(done, false);
}

void Progress::finish() {
  std::lock_guard lock(drawing_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(done_.load(), true);
}

void Progress::draw(size_t done, bool final) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = std::min(1.0, double(done) / double(total_));
  constexpr int kWidth = 30;
  const int filled = int(fraction * kWidth);
  const std::string bar = std::string(filled, '#') + std::string(kWidth - filled, '.');
  if (final)
    std::fprintf(stderr, "\r%s [%s] %3.0f%%  %.1fs          \n", label_.c_str(), bar.c_str(), fraction * 100.0, elapsed);
  else
    std::fprintf(stderr, "\r%s [%s] %3.0f%%  %.1fs, ETA %.1fs   ", label_.c_str(), bar.c_str(), fraction * 100.0, elapsed,
                 fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0);
  std::fflush(stderr);
}

}  // namespace glossy
