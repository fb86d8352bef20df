// Every VPL's hemispherical shadow map (instant radiosity, seed 002), kept between frames: they
// depend on the VPLs and the scene only, so a camera move shades from the same maps and only a
// new trace (moving lights, a new seed) renders them again. Batches of kBatch VPLs, one layered
// instanced draw and one array texture each.
#pragma once
#include <vector>

#include "gl/Objects.h"
#include "src/scene/Scene.h"
#include "src/solver/VplTracer.h"

namespace hemirad {

class VplShadowMaps {
 public:
  static constexpr int kBatch = 256;  // VPLs per draw (layers of one array texture)

  VplShadowMaps(const Scene& scene, const VplTracer& tracer, const InstantSettings& settings);
  // Renders every VPL's map from the tracer's current VPL buffer.
  void render();
  bool rendered() const { return rendered_; }
  unsigned batches() const { return unsigned(ids_.size()); }
  // Batch b's polygon-id maps (VPL b x kBatch + layer) on texture unit `unit`.
  void bind(unsigned batch, unsigned unit) const;

 private:
  const VplTracer& tracer_;
  unsigned vpls_;
  int size_;
  gl::Program program_;
  gl::Buffer vertices_, indices_;
  gl::VertexArray vao_;
  std::size_t indexCount_ = 0;
  gl::Texture depth_;             // shared: only the draw needs it
  std::vector<gl::Texture> ids_;  // per batch
  std::vector<gl::Framebuffer> targets_;
  bool rendered_ = false;
};

}  // namespace hemirad
