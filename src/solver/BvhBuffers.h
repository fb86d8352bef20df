// The scene's BVH (src/solver/Bvh.h) on the GPU, as shaders/bvh.glsl reads it: its nodes and
// triangles in the two storage buffers every tracer binds (the VPL tracer, the reference path
// tracer, per-pixel direct light, near-shooter refinement and --visibility bvh, validation).
#pragma once
#include "gl/Objects.h"
#include "src/solver/Bvh.h"

namespace hemirad {

class BvhBuffers {
 public:
  BvhBuffers() = default;  // empty: for a solver that traces nothing
  explicit BvhBuffers(const Bvh& bvh);
  void bind() const;  // SSBO_BVH_NODES and SSBO_BVH_TRIANGLES

 private:
  gl::Buffer nodes_, triangles_;
};

}  // namespace hemirad
