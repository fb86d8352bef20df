// The device's ceilings for the solver's kinds of work, so `hemirad bench` can print each
// throughput as a fraction of what the GPU can do.
#pragma once
#include <string>

#include "gl/Backend.h"

namespace hemirad {

struct Ceilings {
  double invocationsPerSecond = 0;  // load-store compute invocations/s (the gather's pattern)
  double trianglesPerSecond = 0;    // item-buffer triangles/s, many small triangles
  double fragmentsPerSecond = 0;    // item-buffer fragments/s, large triangles (fill rate)
};

// Best of 5 timed repetitions after a warm-up each; the triangle ceiling draws the item mesh of
// `scenePath` at L = 6 from the middle of its top, facing down.
Ceilings measureCeilings(gl::RenderBackend& backend, const std::string& scenePath);

}  // namespace hemirad
