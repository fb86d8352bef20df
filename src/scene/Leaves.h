// Adaptive subdivision's layout (issue 31; seed 003 section 39.3): every planar chart of the
// uniform atlas is tiled by leaves of kLeafCells x kLeafCells cells, each the root of a quadtree;
// a split leaf's four children keep its cell count at half the cell side, to a maximum depth.
// The refined layout is a scene whose polygons are the charts' parts cut along the leaves, with
// one chart for a chart's unsplit tiles (its own grid) and one per split node (its unsplit
// children, at their finer cells): polygons and charts stay one to one, so the solver, the
// checkpoints (the layout hash holds the cell sizes), the PLY, the lightmap and the camera all
// follow without knowing of leaves.
#pragma once
#include <cstdint>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

inline constexpr int kLeafCells = 16;     // the seed's 16 x 16 texel blocks
inline constexpr int kMaxLeafDepth = 4;   // children of a 16-cell leaf at depth 4: 1 base cell
inline constexpr int kUnitsPerCell = 16;  // node rectangles in 1/16 of a base cell: integers to depth 4
inline constexpr int kNoLeaf = -1;

struct LeafNode {
  int chart = 0;        // of the base (uniform) atlas
  glm::ivec4 rect{0};   // lo x, lo y, hi x, hi y in units of the chart's base grid
  int depth = 0;        // cells of side texelSize / 2^depth
  int firstChild = -1;  // four children from here, or -1 (a leaf)
  bool leaf() const { return firstChild < 0; }
};

class LeafTree {
 public:
  LeafTree(const Atlas& base, int maxDepth);
  const Atlas& base() const { return base_; }
  int maxDepth() const { return maxDepth_; }
  const std::vector<LeafNode>& nodes() const { return nodes_; }
  std::size_t leafCount() const;
  // Splits leaf `node` into four; false (nothing changes) at the maximum depth or on a curved chart.
  bool split(int node);
  // The leaf holding point p of base chart `chart` (plane coordinates of its frame), or kNoLeaf.
  int leafAt(int chart, glm::dvec2 p) const;

 private:
  const Atlas& base_;
  int maxDepth_;
  std::vector<LeafNode> nodes_;
  std::vector<glm::ivec2> tiles_;  // per chart: its tiles across, up
  std::vector<int> firstTile_;     // per chart: its first tile node
};

struct RefinedLayout {
  Scene scene;
  std::vector<ChartSpec> specs;
  std::vector<int> specChart;  // per spec: the base chart it lies on
};

// Chart c as it is, its polygons copied into `into` (renumbered): a spec that grids them as c does.
ChartSpec copyChart(const Scene& scene, const Chart& c, Scene& into);
// The scene cut along the tree's leaves and the charts that grid it (see above). A chart with no
// split leaf keeps its polygons, parts and grid as they are.
RefinedLayout refineLayout(const Scene& scene, const LeafTree& tree);
// Per texel of `atlas`, the tree's leaf its centre lies in, or kNoLeaf; baseChart: per chart of
// `atlas`, the base chart it lies on (RefinedLayout::specChart; 0, 1, 2, ... for the base atlas).
std::vector<std::int32_t> leafOfTexel(const Atlas& atlas, const std::vector<int>& baseChart, const LeafTree& tree);

}  // namespace hemirad
