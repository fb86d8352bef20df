// A bounding-volume hierarchy over the scene's triangles, built on the CPU (binned surface-area
// heuristic, median splits where it finds none) and flattened in preorder into std430 arrays that the
// shaders walk (shaders/bvh.glsl). Every struct is whole vec4s: drivers pad smaller members
// differently (seed 002 §4.1), vec4s they cannot. The CPU traversal mirrors the shader's, for tests.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "src/scene/Scene.h"

namespace hemirad {

// Preorder: an inner node's first child follows it. lo.w: for an inner node the index just past
// its subtree (where a walk that skips it goes on; a leaf's is the next index), for a leaf its
// first triangle; hi.w: the leaf's triangle count, 0 for an inner node. Both stored as uint bits.
// So a walk needs no stack (bvh.glsl's bvhNext): llvmpipe pays for a per-invocation array at every
// push and pop, and loses nodes when one stack walk calls another (docs/design.md#visibility).
struct BvhNode {
  glm::vec4 lo, hi;
};
static_assert(sizeof(BvhNode) == 32);

// v0.w: the triangle's polygon id (uint bits); e1 = v1 - v0, e2 = v2 - v0.
struct BvhTriangle {
  glm::vec4 v0, e1, e2;
};
static_assert(sizeof(BvhTriangle) == 48);

struct BvhHit {
  float t = 0;
  std::uint32_t polygon = 0, triangle = 0;
};

class Bvh {
 public:
  static constexpr int kLeafSize = 2;
  static constexpr int kMaxDepth = 32;  // median splits below this; bounds the build's recursion

  explicit Bvh(const Scene& scene);
  const std::vector<BvhNode>& nodes() const { return nodes_; }
  const std::vector<BvhTriangle>& triangles() const { return triangles_; }
  int depth() const { return depth_; }
  // The nearest hit along origin + t dir, t > 0, ignoring polygon `skip` (the ray's own: a
  // planar polygon cannot occlude itself, and skipping it needs no offset epsilon).
  std::optional<BvhHit> intersect(glm::vec3 origin, glm::vec3 dir, std::uint32_t skip) const;
  // The same by testing every triangle: the reference the traversal must agree with.
  std::optional<BvhHit> intersectAll(glm::vec3 origin, glm::vec3 dir, std::uint32_t skip) const;

 private:
  int build(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, int depth);
  std::size_t splitBySah(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, glm::vec3 clo,
                         glm::vec3 chi);
  static int binOf(float c, float lo, float extent);
  std::uint32_t next(std::uint32_t n, bool enter) const;
  std::vector<BvhNode> nodes_;
  std::vector<BvhTriangle> triangles_;
  std::vector<glm::vec3> centroids_;
  int depth_ = 0;
};

std::uint32_t floatBitsToUint(float f);
float uintBitsToFloat(std::uint32_t u);

}  // namespace hemirad
