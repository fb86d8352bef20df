// Per-pixel final gather of the near field for camera images (issue 31, `--final-gather near`,
// docs/design.md#final-gather): what shaders/near_gather.glsl reads beside per-pixel direct light.
// The atlas cut into 16 x 16-texel blocks (Atlas::shooterBlocks(4)) with quadtrees down to single
// elements (src/solver/ShooterTree.h), each node's exact shape and the mean light its elements send
// on. A pixel regathers the nodes near it at its own point and at the centres its lookup blends.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

// A node is near a point within this many of its radii (centre to farthest corner) of its centre,
// 2 sides of a square: the light of nodes farther off changes little across an element, which the
// lookup's blend follows (docs/design.md#final-gather).
inline constexpr double kGatherReach = 2.0 * 1.41421356;

// B - E per element (atlas order): the light each sends on by reflection, what the pixels' gather
// sees again beside per-pixel direct light.
std::vector<glm::vec4> sentOn(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B);

class NearGather {
 public:
  // `sent`: per element (atlas order) the light it sends on that the pixels' gather should see
  // again: B - E where direct light is computed per pixel.
  NearGather(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& sent);
  static gl::Defines defines() { return {{"NEAR_GATHER", "1"}}; }
  // Binds the nodes, their shapes with the emitter pieces after them (formfactor.glsl's one shape
  // table; direct.glsl's `emitterBase`) and sources, and sets near_gather.glsl's uniforms.
  void bind(const gl::Program& program) const;
  // The blocks (roots) a draw gathers: [first, end) of blocks() (Renderer::drawDirect).
  void bindBlocks(const gl::Program& program, unsigned first, unsigned end) const;
  unsigned blocks() const { return blocks_; }

 private:
  gl::Buffer nodes_, shapes_, sources_;
  unsigned blocks_ = 0, emitterBase_ = 0;
};

}  // namespace hemirad
