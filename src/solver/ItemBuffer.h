// The item buffer (seed 003 §39.2.1): the item mesh, held in a static vertex buffer, rasterised
// from each shooter named in a control block into an R32UI polygon-id target with a depth of
// distance / far, one layer per shooter (and hemicube face). The mesh is cut into chunks of
// consecutive triangles; a compute pass (cull_items.comp) lists per layer the chunks it may see
// and one indirect draw renders them all, so a shooter draws what lies above its horizon (and in
// each hemicube face's frustum), not the whole scene five times. The gather and the validation
// probe look receivers up in it (shaders/visibility.glsl).
#pragma once
#include <string>
#include <vector>

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "src/scene/Scene.h"
#include "src/solver/Projection.h"
#include "src/solver/SolverState.h"

namespace hemirad {

// The shader defines that select projection p in shaders/hemisphere.glsl.
gl::Defines itemBufferDefines(Projection p);

// Binds what a shooter lookup reads besides an item buffer: the scene, the pass's `control` and the
// shooters' `shapes` (formfactor.glsl); all a gather traced through the BVH needs.
void bindShooterLookup(const SolverState& state, const gl::Buffer& control, const gl::Buffer& shapes);

class ItemBuffer {
 public:
  // `resolution` is the pixel budget's side: the hemisphere gets resolution^2 pixels, the
  // hemicube five faces of side resolution / sqrt(3) (top + four half faces = the same budget).
  // `shooters`: the most shooters one render() draws (layers are allocated for each).
  ItemBuffer(const Scene& scene, int subdivision, int resolution, double farDistance,
             Projection projection = Projection::Orthographic, int shooters = 1);
  // Shader defines that select the projection: every program that looks receivers up needs them.
  const gl::Defines& defines() const { return defines_; }
  // Draws from the shooters of the pass in `control` (SSBO_CONTROL); layers past its shooter count
  // stay empty, and every triangle is clipped away once the GPU's stop rule has fired.
  void render(const gl::Buffer& control);
  // Binds what shaders/visibility.glsl reads: the scene, the id target, the pass's `control`
  // and the shooters' `shapes` (formfactor.glsl).
  void bindForLookup(const SolverState& state, const gl::Buffer& control, const gl::Buffer& shapes) const;
  std::size_t triangles() const { return indexCount_ / 3; }
  // Pixels one shooter's item buffer covers (all its faces): the fill work of a shot.
  std::size_t pixelsPerShooter() const { return std::size_t(faces_) * faceResolution_ * faceResolution_; }

 private:
  Projection projection_;
  int faceResolution_;
  int faces_, shooters_;
  gl::Defines defines_;
  gl::Program program_, cull_;
  gl::Buffer vertices_, indices_;
  gl::Buffer chunks_;    // per chunk: bounds and index range (cull_items.comp)
  gl::Buffer commands_;  // per layer and chunk: its indirect draw
  gl::Buffer layers_;    // 0, 1, ...: each draw's layer, by its baseInstance
  std::size_t chunkCount_ = 0;
  gl::Buffer planes_;  // per polygon: unit normal, offset n . p (exact depths)
  gl::VertexArray vao_;
  gl::Texture id_, depth_;
  gl::Framebuffer target_;  // layered: the vertex shader picks the layer
  std::size_t indexCount_ = 0;
};

}  // namespace hemirad
