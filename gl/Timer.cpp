#include "gl/Timer.h"

#include <algorithm>

#include "gl/Backend.h"

namespace hemirad::gl {

TimerMode contextTimerMode(TimerMode mode) {
  const bool stamps = mode == TimerMode::Gpu || mode == TimerMode::GpuEveryPass;
  return stamps && softwareRenderer() ? TimerMode::Synchronous : mode;
}

void GpuTimer::mark(int slot) {
  if (mode_ == TimerMode::Off) return;
  if (mode_ == TimerMode::Synchronous) {
    glFinish();
    cpuMarks_.emplace_back(std::chrono::steady_clock::now(), slot);
    return;
  }
  Query q;
  if (free_.empty()) {
    q = Query(GL_TIMESTAMP);
  } else {
    q = std::move(free_.back());
    free_.pop_back();
  }
  glQueryCounter(q.id(), GL_TIMESTAMP);
  pending_.emplace_back(std::move(q), slot);
}

void GpuTimer::collect(std::span<double> totals, bool wait) {
  for (size_t i = 0; i + 1 < cpuMarks_.size(); ++i)
    if (cpuMarks_[i].second >= 0)
      totals[size_t(cpuMarks_[i].second)] +=
          std::chrono::duration<double, std::milli>(cpuMarks_[i + 1].first - cpuMarks_[i].first).count();
  cpuMarks_.clear();
  std::size_t stamped = pending_.size();  // stamps complete in order: a prefix is ready
  if (!wait)
    for (stamped = 0; stamped < pending_.size() && pending_[stamped].first.available();) ++stamped;
  for (size_t i = 0; i + 1 < stamped; ++i) {
    int slot = pending_[i].second;
    if (slot >= 0) totals[size_t(slot)] += double(pending_[i + 1].first.result() - pending_[i].first.result()) * 1e-6;
  }
  // Kept: the last stamp read, where it starts an interval whose end is not read yet.
  const bool closed = stamped == pending_.size() && (pending_.empty() || pending_.back().second < 0);
  const std::size_t done = closed ? stamped : std::max<std::size_t>(stamped, 1) - 1;
  for (std::size_t i = 0; i < done; ++i) free_.push_back(std::move(pending_[i].first));
  pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(done));
}

}  // namespace hemirad::gl
