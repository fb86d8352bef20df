// Shooter blocks cut where their unshot radiosity is not uniform. Each block is the root of a
// quadtree of up to `depth` levels; a pass ranks whole blocks, then each chosen block shoots
// the part of itself that holds its light: while a node's unshot radiosity varies by more than
// a factor (select.comp), it descends into its child with the most unshot power. A coarse
// block half under a box, or across a shadow edge, thus shoots its lit part from that part's
// exact shape instead of spreading the light over the dark part, which receivers beside the
// box would see only in part (the coarse plan was 2-4 % dark on the Cornell blocks).
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"

namespace hemirad {

inline constexpr std::uint32_t kNoChild = 0xFFFFFFFFu;
inline constexpr int kMaxSplitDepth = 4;  // 256 leaves: node_stats.comp gives each leaf a thread of 256

// A node, std430 (shooter_block.glsl). Nodes [0, blocks) are the blocks themselves; the
// descendants of a block follow in breadth-first order, its leaves contiguous.
struct ShooterNode {
  glm::ivec4 rect;             // atlas x, y, w, h (w = 0: empty, past the chart's edge)
  glm::vec4 centreArea{0.0f};  // area-weighted centre of its elements, their area
  std::uint32_t polygon = kNoPolygon;
  std::uint32_t firstChild = kNoChild;  // four consecutive children, or a leaf
  std::uint32_t firstLeaf = 0;          // blocks only: their leaves, 4^depth of them
  std::uint32_t depth = 0;              // blocks only: levels below the block
  glm::vec4 normal{0.0f};  // xyz: a planar chart's normal, or a curved one's area-weighted mean over the node;
                           // w: its radius, from its centre to its farthest element's corner
};
static_assert(sizeof(ShooterNode) == 64);

struct ShooterTree {
  std::vector<ShooterNode> nodes;
  std::size_t blocks = 0;
  unsigned largestBlock = 1;  // texels in the largest block
  int depth = 0;              // of the deepest block
};

// Threads node_stats.comp gives block b: one per texel of its largest leaf times its leaves (so
// each thread sums at most one texel), a power of two in [16, 256], never fewer than its leaves.
// Blocks share a workgroup size by this, so a scene of many small charts does not run 256
// threads for each 4-texel block; the sums are those of a single size (one texel a thread).
unsigned statsThreads(const ShooterTree& tree, std::size_t block);

// `depth` (0..kMaxSplitDepth) levels below every block, fewer for blocks too small to cut.
ShooterTree buildShooterTree(const Atlas& atlas, const std::vector<ShooterBlock>& blocks, int depth);

}  // namespace hemirad
