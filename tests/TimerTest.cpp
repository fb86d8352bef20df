#include <catch2/catch.hpp>

#include "gl/Timer.h"

using hemirad::gl::GpuTimer;
using hemirad::gl::TimerMode;

// Which passes a solver stamps (the bench's split needs them all on a hardware GPU; a solve's own
// timings stamp a sample, whose totals are scaled; untimed runs pay for none).
TEST_CASE("GPU timing stamps one pass in 16 by default, every pass for the bench's split, and none when off",
          "[timer]") {
  unsigned sampled = 0, every = 0, synchronous = 0, off = 0;
  for (unsigned pass = 0; pass < 64; ++pass) {
    sampled += GpuTimer(TimerMode::Gpu).due(pass);
    every += GpuTimer(TimerMode::GpuEveryPass).due(pass);
    synchronous += GpuTimer(TimerMode::Synchronous).due(pass);
    off += GpuTimer(TimerMode::Off).due(pass);
  }
  CHECK(sampled == 64 / GpuTimer::kStride);
  CHECK(GpuTimer(TimerMode::Gpu).due(0));
  CHECK(every == 64);
  CHECK(synchronous == 64);
  CHECK(off == 0);
}
