// The scene's BVH (src/solver/Bvh.h) on the GPU, as shaders/bvh.glsl reads it: its nodes and
// triangles in the two storage buffers every tracer binds (the VPL tracer, the reference path
// tracer, per-pixel direct light, near-shooter refinement and --visibility bvh, validation), and
// the flag its walks set where llvmpipe's loop limit cut one short (bvh.glsl's walkEnded).
#pragma once
#include <string_view>

#include "gl/Objects.h"
#include "src/solver/Bvh.h"

namespace hemirad {

class BvhBuffers {
 public:
  BvhBuffers() = default;  // empty: for a solver that traces nothing
  explicit BvhBuffers(const Bvh& bvh);
  void bind() const;  // SSBO_BVH_NODES, SSBO_BVH_TRIANGLES and SSBO_WALKS_CUT
  // Whether a walk since the BVH was made (or the last clear) ended unfinished: its answer would
  // be wrong. Waits for the GPU; a tracer asks once its results are read.
  bool walksCut() const;
  void clearWalksCut() const;
  // Throws, naming `what`, where walksCut().
  void requireWholeWalks(std::string_view what) const;

 private:
  gl::Buffer nodes_, triangles_;
  mutable gl::Buffer walksCut_;  // the walks' flag, which a retry clears
};

}  // namespace hemirad
