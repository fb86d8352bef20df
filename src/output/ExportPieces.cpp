#include "src/output/ExportPieces.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <unordered_map>

namespace hemirad {

namespace {

bool before(const glm::dvec3& x, const glm::dvec3& y) { return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z); }

// The cut vertices by grid cell: a side finds those lying on it in the cells it passes, whichever
// polygon made them (a neighbour's side may be longer than this one's, its corners elsewhere:
// meshes with T-junctions of their own, as the Cornell box's ceiling around its light). A vertex
// is filed in every cell within a quarter cell of it (per axis), and a side looks in the cells of
// points half a cell apart along it: each point of the side is within a quarter cell of one.
class CutGrid {
 public:
  explicit CutGrid(double cell) : cell_(cell) {}
  void add(const glm::dvec3& p) {
    std::array<Key, 8> keys;
    for (int k = 0; k < 8; ++k)
      keys[std::size_t(k)] = key(p + 0.25 * cell_ * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
    std::sort(keys.begin(), keys.end());
    const auto end = std::unique(keys.begin(), keys.end());
    for (auto k = keys.begin(); k != end; ++k) cells_[*k].push_back(p);
  }
  // Calls f on the vertices filed where segment a -> b passes: a superset of those on it, some
  // more than once.
  template <class F>
  void forEachNear(const glm::dvec3& a, const glm::dvec3& b, F f) const {
    const int steps = int(std::ceil(2 * glm::length(b - a) / cell_));
    for (int i = 0; i <= steps; ++i)
      if (const auto found = cells_.find(key(a + (b - a) * (steps ? double(i) / steps : 0.0))); found != cells_.end())
        for (const glm::dvec3& p : found->second) f(p);
  }

 private:
  using Key = std::array<std::int64_t, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k[0] * 73856093) ^ std::size_t(k[1] * 19349663) ^ std::size_t(k[2] * 83492791);
    }
  };
  Key key(const glm::dvec3& p) const {
    return {std::int64_t(std::floor(p.x / cell_)), std::int64_t(std::floor(p.y / cell_)),
            std::int64_t(std::floor(p.z / cell_))};
  }
  double cell_;
  std::unordered_map<Key, std::vector<glm::dvec3>, Hash> cells_;
};

// Where p lies along a -> b (0 at a, 1 at b), or -1 when it is off the side (beyond 1e-9 of its length).
double along(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 d = b - a;
  const double length2 = glm::dot(d, d), t = glm::dot(p - a, d) / length2;
  const glm::dvec3 off = p - (a + t * d);
  return t >= -1e-9 && t <= 1 + 1e-9 && glm::dot(off, off) <= 1e-18 * length2 ? t : -1;
}

// The polygon's side holding both p and q, or -1.
int sideOf(const Poly3& v, const glm::dvec3& p, const glm::dvec3& q) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 &a = v[i], &b = v[(i + 1) % v.size()];
    if (along(p, a, b) >= 0 && along(q, a, b) >= 0) return int(i);
  }
  return -1;
}

std::vector<SurfacePiece> cutPolygon(const Scene& scene, const Atlas& atlas, const Lightmap& map, int id) {
  SurfacePiece corners;
  for (const glm::dvec3& v : scene.polygons()[std::size_t(id)].vertices)
    corners.push_back({v, atlas.atlasCoord(id, v), atlas.chartCoord(id, v)});
  if (!atlas.charts[atlas.chartOf[std::size_t(id)]].uvMapped()) return map.affinePieces(atlas, id, corners);
  std::vector<SurfacePiece> pieces;  // a UV chart's map is affine per fan triangle
  for (std::size_t k = 1; k + 1 < corners.size(); ++k)
    for (SurfacePiece& piece : map.affinePieces(atlas, id, {corners[0], corners[k], corners[k + 1]}))
      pieces.push_back(std::move(piece));
  return pieces;
}

// The cut vertices strictly inside side p -> q of a piece of `polygon`, in order from p, their
// atlas and chart coordinates interpolated along the side (affine over the piece).
SurfacePiece cutsAlong(const Poly3& polygon, const SurfacePoint& p, const SurfacePoint& q, const CutGrid& cuts) {
  if (sideOf(polygon, p.position, q.position) < 0) return {};  // inside the polygon: no neighbour there
  std::vector<std::pair<double, glm::dvec3>> between;
  cuts.forEachNear(p.position, q.position, [&](const glm::dvec3& c) {
    const double s = along(c, p.position, q.position);
    if (s > 1e-9 && s < 1 - 1e-9) between.emplace_back(s, c);
  });
  std::sort(between.begin(), between.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && before(a.second, b.second));
  });
  between.erase(std::unique(between.begin(), between.end()), between.end());
  SurfacePiece out;
  for (const auto& [s, c] : between)
    out.push_back({c, p.atlas + s * (q.atlas - p.atlas), p.plane + s * (q.plane - p.plane)});
  return out;
}

// `piece` with the cut vertices on its sides inserted; false when there are none.
bool weld(const Poly3& polygon, const CutGrid& cuts, SurfacePiece& piece) {
  std::vector<SurfacePiece> inserted(piece.size());
  bool any = false;
  for (std::size_t i = 0; i < piece.size(); ++i)
    any |= !(inserted[i] = cutsAlong(polygon, piece[i], piece[(i + 1) % piece.size()], cuts)).empty();
  if (!any) return false;
  SurfacePiece welded;
  for (std::size_t i = 0; i < piece.size(); ++i) {
    welded.push_back(piece[i]);
    welded.insert(welded.end(), inserted[i].begin(), inserted[i].end());
  }
  piece = std::move(welded);
  return true;
}

}  // namespace

std::vector<ExportPolygon> exportPieces(const Scene& scene, const Atlas& atlas, const Lightmap& map) {
  const std::vector<ScenePolygon>& polygons = scene.polygons();
  std::vector<ExportPolygon> out(polygons.size());
  // The cut vertices on the polygons' sides, in cells of a quarter texel (a few vertices a cell).
  CutGrid cuts(atlas.texelSize / 4);
  for (std::size_t id = 0; id < polygons.size(); ++id) {
    out[id].pieces = cutPolygon(scene, atlas, map, int(id));
    const Poly3& v = polygons[id].vertices;
    for (const SurfacePiece& piece : out[id].pieces)
      for (const SurfacePoint& p : piece)
        if (std::find(v.begin(), v.end(), p.position) == v.end() && sideOf(v, p.position, p.position) >= 0)
          cuts.add(p.position);
  }
  for (std::size_t id = 0; id < polygons.size(); ++id) {
    ExportPolygon& e = out[id];
    e.welded.assign(e.pieces.size(), 0);
    for (std::size_t k = 0; k < e.pieces.size(); ++k) e.welded[k] = weld(polygons[id].vertices, cuts, e.pieces[k]);
  }
  return out;
}

}  // namespace hemirad
