#include "gl/Timer.h"

namespace hemirad::gl {

void GpuTimer::begin(int slot) {
  Query q;
  if (free_.empty()) {
    q = Query(GL_TIME_ELAPSED);
  } else {
    q = std::move(free_.back());
    free_.pop_back();
  }
  glBeginQuery(GL_TIME_ELAPSED, q.id());
  pending_.emplace_back(std::move(q), slot);
}

void GpuTimer::end() { glEndQuery(GL_TIME_ELAPSED); }

void GpuTimer::collect(std::span<double> totals) {
  for (auto& [q, slot] : pending_) {
    totals[size_t(slot)] += double(q.result()) * 1e-6;
    free_.push_back(std::move(q));
  }
  pending_.clear();
}

}  // namespace hemirad::gl
