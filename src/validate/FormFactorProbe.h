// The GPU side of validation: for one shooter element, the item buffer and each receiver's
// visibility and exact form factor exactly as the gather computes them (shaders/visibility.glsl),
// read back instead of applied; `traced`: the visibility of --visibility bvh, no item buffer drawn.
#pragma once
#include <memory>
#include <vector>

#include "src/solver/BvhBuffers.h"
#include "src/solver/ItemBuffer.h"
#include "src/solver/SolverState.h"

namespace hemirad {

struct ProbeSample {
  float visible, formFactor, facing, pad;
};

class FormFactorProbe {
 public:
  FormFactorProbe(const SolverState& state, int subdivision, int resolution, Projection projection,
                  bool traced = false);
  std::vector<ProbeSample> fromShooter(std::size_t shooterTexel);
  std::size_t itemTriangles() const { return itemBuffer_.triangles(); }
  double gpuMilliseconds() const { return gpuMs_; }  // item buffer + probe, synchronised

 private:
  const SolverState& state_;
  ItemBuffer itemBuffer_;
  gl::Program program_;
  gl::Buffer control_, shape_;
  bool traced_;
  BvhBuffers bvh_;  // traced only
  gl::Texture result_;
  double gpuMs_ = 0;
};

}  // namespace hemirad
