// The item buffer (seed 003 §39.2.1): the item mesh, held in a static vertex buffer, rasterised
// from the shooter named in a control block into an R32UI polygon-id target with a depth of
// distance / far. The gather and the validation probe look receivers up in it
// (shaders/visibility.glsl).
#pragma once
#include "gl/Objects.h"
#include "src/Scene.h"

namespace hemirad {

class ItemBuffer {
 public:
  ItemBuffer(const Scene& scene, int subdivision, int resolution, double farDistance);
  // Draws from the shooter in `control` (SSBO 3), with its indirect draw arguments, so the
  // draw is empty once the GPU's stop rule has fired.
  void render(const gl::Buffer& control);
  // Binds the id and depth targets to texture units 2 and 3.
  void bindForLookup() const;
  std::size_t triangles() const { return vertexCount_ / 3; }
  std::size_t vertexCount() const { return vertexCount_; }
  int resolution() const { return resolution_; }

 private:
  int resolution_;
  gl::Program program_;
  gl::Buffer vertices_;
  gl::VertexArray vao_;
  gl::Texture id_, depth_;
  gl::Framebuffer fbo_;
  std::size_t vertexCount_ = 0;
};

}  // namespace hemirad
