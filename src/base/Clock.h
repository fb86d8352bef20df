// The clock every timing in hemirad reads (benchmarks, reports, the viewer's frame budget).
#pragma once
#include <chrono>

namespace hemirad {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

}  // namespace hemirad
