#include "src/solver/ShooterTree.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace hemirad {

namespace {

// How far a node reaches from its centre: to its farthest element centre plus half a texel's
// diagonal. A node at a chart's edge may be a sliver (1 x 16 texels), whose area says nothing of it.
double nodeRadius(const Atlas& atlas, glm::ivec4 rect, const glm::dvec3& centre) {
  double radius = 0;
  for (int y = rect.y; y < rect.y + rect.w; ++y)
    for (int x = rect.x; x < rect.x + rect.z; ++x) {
      const std::size_t t = std::size_t(y) * atlas.width + x;
      if (atlas.polygonOf[t] != kNoPolygon && atlas.positionArea[t].w > 0)
        radius = std::max(radius, glm::length(glm::dvec3(atlas.positionArea[t]) - centre));
    }
  const std::uint32_t chart = atlas.chartUnder(rect);
  if (chart != kNoPolygon && atlas.charts[chart].clustered) {  // its parts lie beyond its cell (Clusters.h)
    for (const Poly3& part : atlas.charts[chart].parts)
      for (const glm::dvec3& v : part) radius = std::max(radius, glm::length(v - centre));
    return radius;
  }
  return radius + atlas.texelSize * std::sqrt(0.5);
}

ShooterNode makeNode(const Atlas& atlas, glm::ivec4 rect) {
  ShooterNode n;
  n.rect = rect;
  glm::dvec3 centre(0.0), normal(0.0);
  double area = 0;
  for (int y = rect.y; y < rect.y + rect.w; ++y)
    for (int x = rect.x; x < rect.x + rect.z; ++x) {
      const std::size_t t = std::size_t(y) * atlas.width + x;
      if (atlas.polygonOf[t] == kNoPolygon || atlas.positionArea[t].w <= 0) continue;
      centre += glm::dvec3(atlas.positionArea[t]) * double(atlas.positionArea[t].w);
      area += atlas.positionArea[t].w;
      normal += glm::dvec3(atlas.normalOf[t]) * double(atlas.positionArea[t].w);
      n.polygon = atlas.polygonOf[t];
      // A planar chart: every element's normal is the plane's (bit for bit a polygon's own).
      if (atlas.charts[atlas.chartOf[n.polygon]].planar) n.normal = glm::vec4(atlas.normalOf[t], 0.0f);
    }
  if (area > 0) n.centreArea = glm::vec4(glm::vec3(centre / area), float(area));
  if (area > 0 && !atlas.charts[atlas.chartOf[n.polygon]].planar)
    n.normal = glm::vec4(glm::vec3(glm::normalize(normal)), 0.0f);
  n.normal.w = float(nodeRadius(atlas, rect, glm::dvec3(n.centreArea)));
  return n;
}

// The four quadrants of `rect` (a square of `side` texels from its corner, cut at the chart's
// edge), empty where the cut leaves nothing.
std::vector<glm::ivec4> quadrants(glm::ivec4 rect, int side) {
  const int h = side / 2;
  std::vector<glm::ivec4> out;
  for (int q = 0; q < 4; ++q) {
    const int x = rect.x + (q & 1) * h, y = rect.y + (q >> 1) * h;
    const int w = std::min(h, rect.x + rect.z - x), ht = std::min(h, rect.y + rect.w - y);
    out.push_back(w > 0 && ht > 0 ? glm::ivec4(x, y, w, ht) : glm::ivec4(x, y, 0, 0));
  }
  return out;
}

}  // namespace

ShooterTree buildShooterTree(const Atlas& atlas, const std::vector<ShooterBlock>& blocks, int depth) {
  ShooterTree tree;
  tree.blocks = blocks.size();
  for (const ShooterBlock& b : blocks) {
    tree.nodes.push_back(makeNode(atlas, b.rect));
    tree.largestBlock = std::max(tree.largestBlock, unsigned(b.rect.z * b.rect.w));
  }
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const int side = int(std::bit_ceil(unsigned(std::max(blocks[b].rect.z, blocks[b].rect.w))));
    const int levels = std::min(depth, std::countr_zero(unsigned(side)));
    tree.nodes[b].depth = std::uint32_t(levels);
    tree.depth = std::max(tree.depth, levels);
    tree.nodes[b].firstLeaf = std::uint32_t(b);
    // Breadth first: level by level, each node's four children appended together.
    std::vector<std::uint32_t> level{std::uint32_t(b)};
    for (int l = 0, s = side; l < levels; ++l, s /= 2) {
      std::vector<std::uint32_t> next;
      for (std::uint32_t parent : level) {
        tree.nodes[parent].firstChild = std::uint32_t(tree.nodes.size());
        for (glm::ivec4 r : quadrants(tree.nodes[parent].rect, s)) {
          next.push_back(std::uint32_t(tree.nodes.size()));
          tree.nodes.push_back(r.z > 0 ? makeNode(atlas, r) : ShooterNode{r});
        }
      }
      level = std::move(next);
    }
    tree.nodes[b].firstLeaf = level.front();
  }
  return tree;
}

unsigned statsThreads(const ShooterTree& tree, std::size_t block) {
  const ShooterNode& b = tree.nodes[block];
  const unsigned leaves = 1u << (2 * b.depth);
  unsigned largestLeaf = 1;
  for (unsigned k = 0; k < leaves; ++k) {
    const glm::ivec4 r = tree.nodes[b.firstLeaf + k].rect;
    largestLeaf = std::max(largestLeaf, unsigned(std::max(r.z, 0) * std::max(r.w, 0)));
  }
  return std::clamp(std::bit_ceil(leaves * largestLeaf), std::max(16u, leaves), 256u);
}

}  // namespace hemirad
