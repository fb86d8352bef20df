#include "src/scene/Leaves.h"

#include <algorithm>
#include <map>

namespace hemirad {

LeafTree::LeafTree(const Atlas& base, int maxDepth) : base_(base), maxDepth_(std::clamp(maxDepth, 0, kMaxLeafDepth)) {
  const int tile = kLeafCells * kUnitsPerCell;
  for (std::size_t c = 0; c < base.charts.size(); ++c) {
    const glm::ivec2 size = base.charts[c].size;
    const glm::ivec2 n = (size + kLeafCells - 1) / kLeafCells;
    tiles_.push_back(n);
    firstTile_.push_back(int(nodes_.size()));
    for (int j = 0; j < n.y; ++j)
      for (int i = 0; i < n.x; ++i) {
        const glm::ivec2 lo(i * tile, j * tile), hi = glm::min(lo + tile, size * kUnitsPerCell);
        nodes_.push_back({int(c), glm::ivec4(lo, hi), 0, -1});
      }
  }
}

std::size_t LeafTree::leafCount() const {
  return std::size_t(std::count_if(nodes_.begin(), nodes_.end(), [](const LeafNode& n) { return n.leaf(); }));
}

bool LeafTree::split(int node) {
  const LeafNode n = nodes_[std::size_t(node)];
  if (!n.leaf() || n.depth >= maxDepth_ || !base_.charts[std::size_t(n.chart)].planar) return false;
  // The middle in units: the node's cells (its tile's count) halve at twice the density, so a
  // child's side is a whole number of its own cells' units (kUnitsPerCell >> (depth + 1)).
  const glm::ivec2 lo(n.rect.x, n.rect.y), hi(n.rect.z, n.rect.w), mid = lo + (hi - lo) / 2;
  nodes_[std::size_t(node)].firstChild = int(nodes_.size());
  for (int k = 0; k < 4; ++k) {
    const glm::ivec2 clo(k & 1 ? mid.x : lo.x, k & 2 ? mid.y : lo.y), chi(k & 1 ? hi.x : mid.x, k & 2 ? hi.y : mid.y);
    nodes_.push_back({n.chart, glm::ivec4(clo, chi), n.depth + 1, -1});
  }
  return true;
}

int LeafTree::leafAt(int chart, glm::dvec2 p) const {
  const Chart& c = base_.charts[std::size_t(chart)];
  const glm::dvec2 u = (p - c.corner) / c.cellSize * double(kUnitsPerCell);
  const glm::ivec2 t(glm::floor(u / double(kLeafCells * kUnitsPerCell)));
  const glm::ivec2 n = tiles_[std::size_t(chart)];
  if (t.x < 0 || t.y < 0 || t.x >= n.x || t.y >= n.y) return kNoLeaf;
  int node = firstTile_[std::size_t(chart)] + t.y * n.x + t.x;
  while (!nodes_[std::size_t(node)].leaf()) {
    const LeafNode& parent = nodes_[std::size_t(node)];
    const LeafNode& first = nodes_[std::size_t(parent.firstChild)];  // lower-left: its hi corner is the middle
    node = parent.firstChild + (u.x >= first.rect.z ? 1 : 0) + (u.y >= first.rect.w ? 2 : 0);
  }
  return node;
}

namespace {

// Cut pieces: polygons of the refined scene on one base chart, by the chart (-1: unsplit tiles;
// else the split node) they lie on.
struct Cutter {
  const Scene& scene;
  const LeafTree& tree;
  RefinedLayout& out;
  std::map<int, int> wholes;  // base polygon -> its index in out.scene.wholes

  // Base chart c's parts clipped to `rect` (units) in squares of the finest node's side, so two
  // charts meet along whole square sides: no T-junctions, seams shared edge for edge
  // (src/output/SeamStitch.h).
  void cut(const Chart& c, glm::ivec4 rect, ChartGroup& group) {
    const int square = kLeafCells * kUnitsPerCell >> tree.maxDepth();
    const double unit = c.cellSize / kUnitsPerCell;
    auto next = [&](int at, int end) { return std::min(end, (at / square + 1) * square); };  // on one global grid
    for (int y = rect.y; y < rect.w; y = next(y, rect.w))
      for (int x = rect.x; x < rect.z; x = next(x, rect.z)) {
        const glm::dvec2 lo = c.corner + glm::dvec2(x, y) * unit;
        const glm::dvec2 hi = c.corner + glm::dvec2(next(x, rect.z), next(y, rect.w)) * unit;
        for (std::size_t k = 0; k < c.parts.size(); ++k) add(c, k, lo, hi, group);
      }
  }

  void add(const Chart& c, std::size_t k, glm::dvec2 lo, glm::dvec2 hi, ChartGroup& group) {
    Poly2 q;
    for (auto& v : c.parts[k]) q.push_back(c.frame.project(v));
    if (!overlapsBox(q, lo, hi)) return;
    const Poly2 piece = clipToBox(q, lo, hi);
    const double finest = c.cellSize / double(1 << tree.maxDepth());
    if (piece.size() < 3 || signedArea(piece) <= kMinCutFraction * finest * finest) return;
    const ScenePolygon& on = scene.polygons()[std::size_t(c.partPolygon[k])];
    Poly3 lifted;
    for (auto& p : piece) lifted.push_back(c.frame.lift(p));
    if (!out.scene.addPolygon(lifted, on.material, on.object)) return;
    const int id = int(out.scene.polygons().size()) - 1;
    auto [whole, added] = wholes.try_emplace(c.partPolygon[k], int(out.scene.wholes.size()));
    if (added) out.scene.wholes.push_back(on);
    out.scene.wholeOf.resize(out.scene.polygons().size(), -1);
    out.scene.wholeOf.back() = whole->second;
    group.polygons.push_back(id), group.parts.push_back(lifted), group.partPolygon.push_back(id);
  }
};

ChartSpec specOf(const Chart& c, ChartGroup group, glm::ivec4 rect, int depth) {
  group.axis = c.frame.n;
  group.planar = true;
  const int units = kUnitsPerCell >> depth;  // a cell's side in units
  return {std::move(group), c.frame, c.corner + glm::dvec2(rect.x, rect.y) * (c.cellSize / kUnitsPerCell),
          glm::ivec2((rect.z - rect.x) / units, (rect.w - rect.y) / units), c.cellSize / double(1 << depth)};
}

}  // namespace

ChartSpec copyChart(const Scene& scene, const Chart& c, Scene& refined) {
  ChartGroup g;
  std::map<int, int> renamed;
  for (int p : c.polygons) {
    const ScenePolygon& poly = scene.polygons()[std::size_t(p)];
    refined.addPolygon(poly.vertices, poly.material, poly.object);
    renamed[p] = int(refined.polygons().size()) - 1;
    g.polygons.push_back(renamed[p]);
  }
  g.axis = c.frame.n;
  g.planar = c.planar;
  g.parts = c.parts;
  g.uv = c.uv;  // an LSCM chart keeps its map (as placed: turned with its grid)
  g.clustered = c.clustered;
  for (int p : c.partPolygon) g.partPolygon.push_back(renamed.at(p));
  return {std::move(g), c.frame, c.corner, c.size, c.cellSize};
}

RefinedLayout refineLayout(const Scene& scene, const LeafTree& tree) {
  RefinedLayout out{sceneLike(scene), {}, {}};
  const Atlas& base = tree.base();
  const auto& nodes = tree.nodes();
  std::vector<char> split(base.charts.size(), 0);
  for (const LeafNode& n : nodes) split[std::size_t(n.chart)] |= !n.leaf();
  Cutter cutter{scene, tree, out, {}};
  for (std::size_t c = 0; c < base.charts.size(); ++c) {
    const Chart& chart = base.charts[c];
    if (!split[c]) {
      out.specs.push_back(copyChart(scene, chart, out.scene)), out.specChart.push_back(int(c));
      continue;
    }
    ChartGroup tiles;  // the unsplit tiles: the chart's own grid
    for (const LeafNode& n : nodes)
      if (n.chart == int(c) && n.depth == 0 && n.leaf()) cutter.cut(chart, n.rect, tiles);
    if (!tiles.parts.empty())
      out.specs.push_back(specOf(chart, std::move(tiles), glm::ivec4(0, 0, chart.size * kUnitsPerCell), 0)),
          out.specChart.push_back(int(c));
    for (const LeafNode& n : nodes) {
      if (n.chart != int(c) || n.leaf()) continue;
      ChartGroup children;  // its unsplit children, at their cells
      for (int k = 0; k < 4; ++k)
        if (const LeafNode& child = nodes[std::size_t(n.firstChild + k)]; child.leaf())
          cutter.cut(chart, child.rect, children);
      if (!children.parts.empty())
        out.specs.push_back(specOf(chart, std::move(children), n.rect, n.depth + 1)), out.specChart.push_back(int(c));
    }
  }
  if (!out.scene.wholes.empty()) out.scene.wholeOf.resize(out.scene.polygons().size(), -1);
  return out;
}

std::vector<std::int32_t> leafOfTexel(const Atlas& atlas, const std::vector<int>& baseChart, const LeafTree& tree) {
  std::vector<std::int32_t> out(atlas.polygonOf.size(), kNoLeaf);
  for (std::size_t id = 0; id < atlas.charts.size(); ++id) {
    const Chart& c = atlas.charts[id];
    const Chart& root = tree.base().charts[std::size_t(baseChart[id])];
    for (int j = 0; j < c.size.y; ++j)
      for (int i = 0; i < c.size.x; ++i) {
        const std::size_t t = std::size_t(c.origin.y + j) * std::size_t(atlas.width) + std::size_t(c.origin.x + i);
        if (atlas.polygonOf[t] == kNoPolygon) continue;
        const glm::dvec3 centre = c.frame.lift(c.corner + (glm::dvec2(i, j) + 0.5) * c.cellSize);
        out[t] = tree.leafAt(baseChart[id], root.frame.project(centre));
      }
  }
  return out;
}

}  // namespace hemirad
