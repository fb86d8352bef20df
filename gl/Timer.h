// Time per pass. By default from GL_TIMESTAMP queries at pass boundaries, read back only at
// sync points so timing never stalls the pipeline. Drivers that defer work (llvmpipe bins
// triangles until a flush) stamp a pass when it is queued, not when it runs, so `synchronous`
// mode instead waits (glFinish) at every boundary and reads the CPU clock: exact per-pass
// splits at the cost of pipelining. `Off` records nothing: untimed runs pay no query per pass.
// A query costs llvmpipe about as much as a pass, so `Gpu` stamps one pass in kStride and the
// totals are scaled; `GpuEveryPass` stamps them all (the bench's split on a hardware GPU, where
// a synchronous split would add a round trip to every stage of a 0.25 ms pass).
#pragma once
#include <chrono>
#include <span>
#include <utility>
#include <vector>

#include "gl/Objects.h"

namespace hemirad::gl {

enum class TimerMode { Off, Gpu, GpuEveryPass, Synchronous };

// The mode a timer of the current context should use: GPU stamps (`Gpu`, `GpuEveryPass`) are
// `Synchronous` on a CPU rasterizer, whose stamps would charge the stages with work queued before
// them (a real_20k solve's report gave select 4,228 ms and gather 4 ms).
TimerMode contextTimerMode(TimerMode mode);

class GpuTimer {
 public:
  static constexpr unsigned kStride = 16;
  explicit GpuTimer(TimerMode mode = TimerMode::Gpu) : mode_(mode) {}
  // Whether pass number `pass` (0, 1, ...) is to be timed.
  bool due(unsigned pass) const { return mode_ == TimerMode::Gpu ? pass % kStride == 0 : mode_ != TimerMode::Off; }
  // Marks the start of pass `slot`; the pass ends at the next mark() or stop().
  void mark(int slot);
  void stop() { mark(-1); }
  // Adds finished passes' milliseconds to totals[slot]: with `wait`, every marked pass's (waiting
  // for the GPU to stamp them); without, those the GPU has stamped already, the rest kept for a
  // later call (a solve running ahead reads its status while the next chunk's stamps are queued).
  void collect(std::span<double> totals, bool wait = true);

 private:
  TimerMode mode_;
  std::vector<Query> free_;
  std::vector<std::pair<Query, int>> pending_;  // timestamp, slot it starts (-1: a stop)
  std::vector<std::pair<std::chrono::steady_clock::time_point, int>> cpuMarks_;
};

}  // namespace hemirad::gl
