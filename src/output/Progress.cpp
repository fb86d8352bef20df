#include "src/output/Progress.h"

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace hemirad {

namespace {
constexpr auto kTtyInterval = std::chrono::milliseconds(100);
constexpr auto kPlainInterval = std::chrono::seconds(5);

std::string duration(double s) {
  if (!std::isfinite(s)) return "?";
  if (s < 60) return fmt::format("{:.1f}s", s);
  if (s < 3600) return fmt::format("{}m{:02}s", int(s / 60), int(s) % 60);
  return fmt::format("{}h{:02}m", int(s / 3600), int(s / 60) % 60);
}
}  // namespace

int terminalColumns() {
  if (const char* c = std::getenv("COLUMNS")) {
    const int n = std::atoi(c);
    if (n > 0) return n;
  }
  winsize w{};
  if (ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 0) return w.ws_col;
  return 80;
}

Progress::Progress(const StopRule& stop, bool enabled)
    : stop_(stop),
      enabled_(enabled),
      tty_(enabled && isatty(STDERR_FILENO)),
      start_(std::chrono::steady_clock::now()),
      lastDraw_(start_) {}

double Progress::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

Progress::Estimate Progress::estimate(const SolveStatus& s, double elapsed) const {
  if (s.done) return {1.0, 0.0};
  if (s.shots == 0) return {0.0, NAN};
  // Shots left to whichever stop comes first: the shot limit, or the model's convergence target.
  double left = INFINITY;
  if (stop_.maxShots > 0) left = double(stop_.maxShots) - double(s.shots);
  if (stop_.targetConvergence > 0 && !std::isnan(s.convergence))
    if (auto model = model_.shotsLeft(stop_.targetConvergence)) left = std::min(left, *model);
  if (!std::isfinite(left)) return {0.0, NAN};
  left = std::max(left, 0.0);
  const bool warmedUp = firstShots_ > 0 && s.shots > firstShots_;
  const double perShot = warmedUp ? (elapsed - firstSeconds_) / double(s.shots - firstShots_) : elapsed / s.shots;
  return {std::max(shownFraction_, double(s.shots) / (s.shots + left)), left * perShot};
}

std::string Progress::barLine(const SolveStatus& s, const Estimate& e, double elapsed, int columns) const {
  // Stochastic iteration has no convergence measure (NaN, docs/design.md#convergence).
  const std::string convergence = std::isnan(s.convergence) ? "" : fmt::format("  convergence {:.4f}", s.convergence);
  const std::string eta = s.done ? duration(elapsed) : "ETA " + duration(e.secondsLeft);
  const std::string tail = fmt::format(" {:3.0f}%  shots {}{}  {}", e.fraction * 100, s.shots, convergence, eta);
  const int width = std::min(40, columns - 1 - int(tail.size()) - 2);  // "[...]" + the tail, one column spare
  if (width < 5) return tail.substr(std::min(tail.size(), std::size_t(1)), std::size_t(std::max(0, columns - 1)));
  const int filled = int(e.fraction * width + 0.5);
  return "[" + std::string(std::size_t(filled), '#') + std::string(std::size_t(width - filled), '.') + "]" + tail;
}

Progress::Estimate Progress::observe(const SolveStatus& s, double elapsed) {
  model_.add(s.shots, s.convergence);
  if (firstShots_ == 0 && s.shots > 0) firstShots_ = s.shots, firstSeconds_ = elapsed;
  const Estimate e = estimate(s, elapsed);
  shownFraction_ = e.fraction;
  return e;
}

void Progress::update(const SolveStatus& s) {
  if (!enabled_) return;
  const double t = elapsedSeconds();
  const Estimate e = observe(s, t);
  auto now = std::chrono::steady_clock::now();
  if (now - lastDraw_ < (tty_ ? std::chrono::duration_cast<std::chrono::milliseconds>(kTtyInterval)
                              : std::chrono::duration_cast<std::chrono::milliseconds>(kPlainInterval)) &&
      !(tty_ && s.done && drawn_))
    return;
  lastDraw_ = now;
  if (tty_) {
    const int columns = terminalColumns();
    const std::string line = barLine(s, e, t, columns);
    // \r, the line, spaces over what a longer earlier line left, all within the width.
    fmt::print(stderr, "\r{}{}", line, std::string(std::size_t(std::max(0, columns - 1 - int(line.size()))), ' '));
    drawn_ = true;
  } else {
    const std::string convergence = std::isnan(s.convergence) ? "" : fmt::format(", convergence {:.4f}", s.convergence);
    fmt::print(stderr, "hemirad: {:.0f}%, {} shots{}, {} elapsed, ETA {}\n", e.fraction * 100, s.shots, convergence,
               duration(t), duration(e.secondsLeft));
  }
  std::fflush(stderr);
}

void Progress::finish() {
  if (tty_ && drawn_) fmt::print(stderr, "\n");
}

}  // namespace hemirad
