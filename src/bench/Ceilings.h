// The device's ceilings for the solver's kinds of work, so `hemirad bench` can print each
// throughput as a fraction of what the GPU can do.
#pragma once
#include <cstddef>
#include <string>

#include "gl/Backend.h"

namespace hemirad {

struct Ceilings {
  double invocationsPerSecond = 0;  // load-store compute invocations/s (the gather's pattern)
  double trianglesPerSecond = 0;    // item-buffer triangles/s, many small triangles
  double fragmentsPerSecond = 0;    // item-buffer fragments/s, large triangles (fill rate)
  int triangleLevel = 6;            // the item mesh level the triangle ceiling drew
};

// Best of 5 timed repetitions after a warm-up each; the triangle ceiling draws the item mesh of
// `scenePath` at L = 6 from the middle of its top, facing down, or at the highest level under
// kCeilingTriangles triangles for a scene too large for L6 (real scenes: docs/real-scenes.md).
inline constexpr std::size_t kCeilingTriangles = std::size_t(1) << 22;
int ceilingLevel(std::size_t sceneTriangles);  // that level: 6, or lower down to 0
Ceilings measureCeilings(gl::RenderBackend& backend, const std::string& scenePath);

}  // namespace hemirad
