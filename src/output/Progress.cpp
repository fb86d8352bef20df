#include "src/output/Progress.h"

#include <cmath>

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace hemirad {

Progress::Progress(const StopRule& stop, bool enabled)
    : stop_(stop), tty_(enabled && isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()), lastDraw_(start_) {}

double Progress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

double Progress::fraction(const SolveStatus& s) const {
  double f = 0;
  if (stop_.targetConvergence > 0) f = std::max(f, s.convergence / stop_.targetConvergence);
  if (stop_.maxShots > 0) f = std::max(f, double(s.shots) / stop_.maxShots);
  return std::clamp(s.done ? 1.0 : f, 0.0, 1.0);
}

void Progress::update(const SolveStatus& s) {
  if (!tty_) return;
  auto now = std::chrono::steady_clock::now();
  if (drawn_ && !s.done && now - lastDraw_ < std::chrono::milliseconds(100)) return;
  lastDraw_ = now;
  drawn_ = true;
  double f = fraction(s), t = elapsedSeconds();
  int width = 30, filled = int(f * width + 0.5);
  std::string eta = f > 0.01 && !s.done ? fmt::format("ETA {:.1f}s", t * (1 - f) / f) : fmt::format("{:.1f}s", t);
  // Stochastic iteration has no convergence measure (NaN, docs/design.md#convergence).
  const std::string convergence = std::isnan(s.convergence) ? "" : fmt::format("  convergence {:.4f}", s.convergence);
  fmt::print(stderr, "\r[{}{}] {:3.0f}%  shots {}{}  {}   ", std::string(size_t(filled), '#'),
             std::string(size_t(width - filled), '.'), f * 100, s.shots, convergence, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (tty_ && drawn_) fmt::print(stderr, "\n");
}

}  // namespace hemirad
