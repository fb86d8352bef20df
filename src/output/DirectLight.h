// Per-pixel direct light for camera images (issue 31, `--direct per-pixel`,
// docs/design.md#per-pixel-direct): what shaders/direct.glsl needs beside the scene tables, the
// emitters cut into pieces of 3 or 4 vertices and the scene's BVH. The renderer draws the view
// twice with camera.frag built with defines(): E + the indirect atlas, then the direct light added.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "src/scene/Scene.h"
#include "src/solver/BvhBuffers.h"

namespace hemirad {

// Visibility samples a piece side: a penumbra pixel's visible share is resolved in steps of about
// 1 / G^2 of the piece's light (supersampled pixels average their samples' steps); lit and
// umbra pixels are exact whatever G (tests/DirectLightGLTest.cpp).
inline constexpr int kDirectGrid = 8;

// On llvmpipe, the loop turns direct.glsl's pyramid test may take before it leaves a piece to the
// exact tests: its walk over the BVH nodes the pyramid's box meets is the one part of a strip's
// work a share cannot split (src/output/DirectShares.h), and in a furnished room it alone passed
// llvmpipe's 65,535. A GPU walks it whole (the exact tests cost more there than the walk).
inline constexpr unsigned kSoftwarePyramidTurns = 8192;

// The emitting polygons as fan pieces of 3 or 4 vertices (v0 v1 v2 v3, v0 v3 v4 v5, ...), each a
// SHAPE_STRIDE slot of formfactor.glsl's layout: the count, one piece (y bits), the polygon id
// (w bits), then the vertices.
std::vector<glm::vec4> emitterPieces(const Scene& scene);

class DirectLight {
 public:
  DirectLight(const Scene& scene, double farDistance, int grid = kDirectGrid);
  static gl::Defines defines() { return {{"PER_PIXEL_DIRECT", "1"}}; }
  // Binds the pieces and the BVH and sets direct.glsl's uniforms on `program`.
  void bind(const gl::Program& program) const;
  // From now on `program` adds the light of strips [first, end) only (src/output/DirectShares.h).
  void bindStrips(const gl::Program& program, unsigned first, unsigned end) const;
  unsigned pieces() const { return pieceCount_; }
  unsigned grid() const { return unsigned(grid_); }  // strips a piece
  unsigned strips() const { return pieceCount_ * grid(); }
  // Where llvmpipe's loop limit cut a walk of the images drawn with it (BvhBuffers.h).
  const BvhBuffers& walks() const { return bvh_; }

 private:
  gl::Buffer pieces_;
  BvhBuffers bvh_;
  unsigned pieceCount_ = 0;
  int grid_;
  float segmentEps_;
};

}  // namespace hemirad
