// --visibility bvh's segment tests answered on the host by Embree, for a CPU device (llvmpipe),
// where the GLSL walk (shaders/bvh_segment.glsl) costs ~90 cycles a node a lane and Embree's SIMD
// BVH answers a segment 20-30x sooner (docs/real-scenes.md#visibility-through-the-bvh). The rule is
// tracedClear's, mirrored here: each end onto its polygon's plane, the shooter's and the receiver's
// charts pass, a curved receiver's last half side untested, and a polygon blocks where the segment
// crosses its plane strictly (blocksSegment's plane test, shaders/segment.glsl) inside one of its
// triangles by Embree's watertight test. Per pass, a bit per receiver (in ReceiverOrder's order)
// and radiosity shooter, which the gather reads (SSBO_HOST_VISIBLE) instead of walking.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "src/scene/Atlas.h"
#include "src/solver/Bvh.h"
#include "src/solver/Control.h"

namespace hemirad {

class HostTrace {
 public:
  // Up to `shooters` radiosity shooters a pass; eps: blocksSegment's plane tolerance
  // (SEGMENT_TOLERANCE x the far distance).
  HostTrace(const Scene& scene, const Atlas& atlas, const Bvh& bvh, std::span<const std::uint32_t> receivers,
            unsigned shooters, float eps);
  ~HostTrace();
  HostTrace(const HostTrace&) = delete;
  HostTrace& operator=(const HostTrace&) = delete;

  unsigned words() const { return words_; }  // per receiver (visibility.glsl's HOST_WORDS)
  // Bit s % 32 of word i * words() + s / 32: receiver i sees the pass's shooter s; pairs facing
  // away from the shooter's plane, which the gather skips, are left 0.
  void trace(std::span<const ShooterRecord> shooters, std::vector<std::uint32_t>& bits) const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
  unsigned words_;
};

}  // namespace hemirad
