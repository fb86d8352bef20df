#include "src/scene/Charts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <unordered_map>

#include "src/scene/InputUv.h"
#include "src/scene/Lscm.h"
#include "src/scene/Welding.h"

namespace hemirad {

namespace {

using EdgeKey = WeldedEdge;

// Polygons sharing an (undirected) welded edge.
std::vector<std::vector<int>> edgeNeighbours(const Welding& w) {
  std::vector<std::vector<int>> out(w.ids.size());
  for (auto& [edge, polys] : polygonsByEdge(w))
    for (int a : polys)
      for (int b : polys)
        if (a != b) out[std::size_t(a)].push_back(b);
  for (auto& n : out) std::sort(n.begin(), n.end()), n.erase(std::unique(n.begin(), n.end()), n.end());
  return out;
}

struct Box2 {
  glm::dvec2 lo, hi;
};

Poly2 projectAlong(const PlaneFrame& f, const Poly3& p) {
  Poly2 out;
  for (auto& v : p) out.push_back(f.project(v));
  return out;
}

// The part of convex `subject` inside convex counter-clockwise `clipper`.
Poly2 clipConvexPolygons(Poly2 subject, const Poly2& clipper) {
  for (std::size_t e = 0; e < clipper.size() && subject.size() >= 3; ++e) {
    glm::dvec2 a = clipper[e], b = clipper[(e + 1) % clipper.size()];
    auto side = [&](glm::dvec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
    Poly2 out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      glm::dvec2 p = subject[i], q = subject[(i + 1) % subject.size()];
      double sp = side(p), sq = side(q);
      if (sp >= 0) out.push_back(p);
      if ((sp >= 0) != (sq >= 0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    subject = std::move(out);
  }
  return subject;
}

Box2 boundsOf(const Poly2& p) {
  Box2 b{glm::dvec2(1e300), glm::dvec2(-1e300)};
  for (auto& v : p) b.lo = glm::min(b.lo, v), b.hi = glm::max(b.hi, v);
  return b;
}

// A curved chart must not fold over itself: a candidate's projection may not overlap a member's
// (beyond rounding), or two surfaces would share texels. The members' projections are kept and
// bucketed in a uniform grid of their bounding boxes, so a candidate meets only its neighbours:
// growing a chart of n polygons is near-linear (checking every member was quadratic: 17 % of a
// real_400k solve's set-up).
class ProjectedMembers {
 public:
  ProjectedMembers(const PlaneFrame& f, double cell) : frame_(f), cell_(cell) {}
  void add(const Poly3& polygon) {
    members_.push_back({projectAlong(frame_, polygon), {}});
    members_.back().box = boundsOf(members_.back().outline);
    const int id = int(members_.size()) - 1;
    if (!forCells(members_.back().box, [&](std::uint64_t key) { grid_[key].push_back(id); })) large_.push_back(id);
  }
  bool overlaps(const Poly3& polygon) const {
    const Poly2 c = projectAlong(frame_, polygon);
    const Box2 box = boundsOf(c);
    const double tiny = 1e-9 * std::abs(signedArea(c));
    auto hits = [&](int id) {
      const Member& m = members_[std::size_t(id)];
      if (glm::any(glm::lessThan(m.box.hi, box.lo)) || glm::any(glm::lessThan(box.hi, m.box.lo))) return false;
      const Poly2 both = clipConvexPolygons(c, m.outline);
      return both.size() >= 3 && std::abs(signedArea(both)) > tiny;
    };
    bool found = std::any_of(large_.begin(), large_.end(), hits);
    const bool bucketed = forCells(box, [&](std::uint64_t key) {
      if (found) return;
      if (auto it = grid_.find(key); it != grid_.end()) found = std::any_of(it->second.begin(), it->second.end(), hits);
    });
    if (!bucketed && !found)  // a candidate over many cells: every member
      for (std::size_t id = 0; id < members_.size() && !found; ++id) found = hits(int(id));
    return found;
  }

 private:
  struct Member {
    Poly2 outline;
    Box2 box;
  };
  static constexpr long kMaxCells = 64;
  // Calls `visit` with each grid cell `box` covers; false (and no call) past kMaxCells cells.
  template <class Visit>
  bool forCells(const Box2& box, Visit visit) const {
    const glm::dvec2 lo = glm::floor(box.lo / cell_), hi = glm::floor(box.hi / cell_);
    const double range = 2e9;  // cell indices as 32-bit integers
    if (!(glm::all(glm::greaterThan(lo, glm::dvec2(-range))) && glm::all(glm::lessThan(hi, glm::dvec2(range)))) ||
        (hi.x - lo.x + 1) * (hi.y - lo.y + 1) > kMaxCells)
      return false;
    for (double y = lo.y; y <= hi.y; ++y)
      for (double x = lo.x; x <= hi.x; ++x)
        visit(std::uint64_t(std::uint32_t(std::int32_t(x))) << 32 | std::uint32_t(std::int32_t(y)));
    return true;
  }
  const PlaneFrame& frame_;
  double cell_;
  std::vector<Member> members_;
  std::unordered_map<std::uint64_t, std::vector<int>> grid_;
  std::vector<int> large_;  // members over kMaxCells cells: checked against every candidate
};

// The merged outline of coplanar members: the boundary edges (those whose reverse no other
// member holds) chained into one loop, collinear vertices dropped. Empty unless that loop is
// convex and its area the members' (a hole, a T-junction or two loops keep the members).
Poly3 mergedOutline(const Scene& scene, const Welding& w, const std::vector<int>& members, glm::dvec3 n) {
  std::map<EdgeKey, int> directed;
  double total = 0;
  for (int p : members) {
    const auto& ids = w.ids[std::size_t(p)];
    for (std::size_t i = 0; i < ids.size(); ++i) ++directed[{ids[i], ids[(i + 1) % ids.size()]}];
    total += scene.polygons()[std::size_t(p)].area;
  }
  std::map<int, int> next;
  for (auto& [e, count] : directed) {
    if (directed.count({e.second, e.first})) continue;
    if (count != 1 || !next.emplace(e.first, e.second).second) return {};
  }
  if (next.empty()) return {};
  std::vector<int> loop{next.begin()->first};
  while (loop.size() <= next.size()) {
    auto it = next.find(loop.back());
    if (it == next.end()) return {};
    if (it->second == loop.front()) break;
    loop.push_back(it->second);
  }
  if (loop.size() != next.size()) return {};
  Poly3 out;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    glm::dvec3 a = w.position[std::size_t(loop[(i + loop.size() - 1) % loop.size()])],
               b = w.position[std::size_t(loop[i])], c = w.position[std::size_t(loop[(i + 1) % loop.size()])];
    if (glm::length(glm::cross(b - a, c - b)) > 1e-9 * glm::length(b - a) * glm::length(c - b)) out.push_back(b);
  }
  if (out.size() < 3 || !isConvex(out, n) || std::abs(area(out) - total) > 1e-9 * total) return {};
  return out;
}

// Whether polygon q may join a chart grown from `seed` (its normal the chart's axis).
bool joins(const Scene& scene, int seed, int q, double cosAngle) {
  const ScenePolygon &s = scene.polygons()[std::size_t(seed)], &p = scene.polygons()[std::size_t(q)];
  return p.material == s.material && p.object == s.object && glm::dot(p.normal, s.normal) > cosAngle;
}

ChartGroup growChart(const Scene& scene, const std::vector<std::vector<int>>& neighbours, int seed, double angle,
                     std::vector<char>& taken) {
  ChartGroup g;
  g.axis = scene.polygons()[std::size_t(seed)].normal;
  const PlaneFrame f = planeFrame(scene.polygons()[std::size_t(seed)].vertices, g.axis);
  const double cosAngle = std::cos(std::max(angle, kCoplanarRadians)), cosPlanar = std::cos(kCoplanarRadians);
  const Box2 seedBox = boundsOf(projectAlong(f, scene.polygons()[std::size_t(seed)].vertices));
  ProjectedMembers members(f, 2 * std::max(seedBox.hi.x - seedBox.lo.x, seedBox.hi.y - seedBox.lo.y));
  std::deque<int> queue{seed};
  taken[std::size_t(seed)] = 1;
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop_front();
    g.polygons.push_back(p);
    members.add(scene.polygons()[std::size_t(p)].vertices);
    for (int q : neighbours[std::size_t(p)]) {
      if (taken[std::size_t(q)] == 1 || !joins(scene, seed, q, cosAngle)) continue;
      const bool coplanar = glm::dot(scene.polygons()[std::size_t(q)].normal, g.axis) > cosPlanar &&
                            std::abs(glm::dot(scene.polygons()[std::size_t(q)].vertices[0] - f.origin, g.axis)) <=
                                1e-9 * (1 + glm::length(scene.polygons()[std::size_t(q)].vertices[0] - f.origin));
      if (!coplanar && members.overlaps(scene.polygons()[std::size_t(q)].vertices)) continue;
      g.planar = g.planar && coplanar;
      taken[std::size_t(q)] = 1;
      queue.push_back(q);
    }
  }
  return g;
}

// The polygons a conformal chart from `seed` would hold: breadth first across welded edges, the
// untaken neighbours of the seed's material and object whose normal lies within `cosAngle` of the
// member they join (a smooth surface) and within `cosSpread` of the seed's (a map of bounded
// distortion), none marked `refused`.
std::vector<int> smoothRegion(const Scene& scene, const std::vector<std::vector<int>>& neighbours, int seed,
                              double cosAngle, double cosSpread, const std::vector<char>& taken,
                              std::vector<int>& stamp) {
  const auto& polys = scene.polygons();
  const int mark = ++stamp.back();  // the last entry counts calls: members carry this call's mark
  std::vector<int> region{seed};
  stamp[std::size_t(seed)] = mark;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const ScenePolygon& p = polys[std::size_t(region[i])];
    for (int q : neighbours[std::size_t(region[i])]) {
      const ScenePolygon& o = polys[std::size_t(q)];
      if (taken[std::size_t(q)] || stamp[std::size_t(q)] == mark || !joins(scene, seed, q, cosSpread) ||
          !(glm::dot(o.normal, p.normal) > cosAngle))
        continue;
      stamp[std::size_t(q)] = mark;
      region.push_back(q);
    }
  }
  return region;
}

// `region` as one LSCM chart (src/scene/Lscm.h): its polygons fanned into triangles over their
// welded vertices; nothing when the map is refused.
std::optional<ChartGroup> conformalChart(const Scene& scene, const Welding& w, const std::vector<int>& region) {
  std::unordered_map<int, int> local;
  std::vector<glm::dvec3> positions;
  std::vector<std::array<int, 3>> triangles;
  for (int p : region) {
    const std::vector<int>& ids = w.ids[std::size_t(p)];
    auto id = [&](std::size_t i) {
      auto [it, added] = local.emplace(ids[i], int(positions.size()));
      if (added) positions.push_back(w.position[std::size_t(ids[i])]);
      return it->second;
    };
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) triangles.push_back({id(0), id(k), id(k + 1)});
  }
  LscmMap map = lscmMap(positions, triangles);
  if (map.outcome != LscmOutcome::Mapped) return std::nullopt;
  ChartGroup g;
  g.polygons = region;
  g.axis = scene.polygons()[std::size_t(region.front())].normal;
  g.planar = false;
  g.uv = std::move(map.uv);
  for (int m : region) {
    const Poly3& v = scene.polygons()[std::size_t(m)].vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k)
      g.parts.push_back({v[0], v[k], v[k + 1]}), g.partPolygon.push_back(m);
  }
  return g;
}

// The LSCM chart grown from `seed`: the smooth region within each of kLscmSpreads in turn until
// one maps; nothing when the region is flat (a projection chart, bit for bit as before) or no
// spread maps (the region's polygons are then refused: projection charts, as before LSCM).
std::optional<ChartGroup> lscmChart(const Scene& scene, const Welding& w,
                                    const std::vector<std::vector<int>>& neighbours, int seed, double angle,
                                    std::vector<char>& taken, std::vector<int>& stamp) {
  const glm::dvec3 axis = scene.polygons()[std::size_t(seed)].normal;
  std::vector<int> region;
  for (double spread : kLscmSpreads) {
    region = smoothRegion(scene, neighbours, seed, std::cos(angle), std::cos(spread * M_PI / 180), taken, stamp);
    const bool curved = std::any_of(region.begin(), region.end(), [&](int p) {
      return !(glm::dot(scene.polygons()[std::size_t(p)].normal, axis) > std::cos(kCoplanarRadians));
    });
    if (!curved) return std::nullopt;
    if (auto g = conformalChart(scene, w, region)) {
      for (int p : region) taken[std::size_t(p)] = 1;
      return g;
    }
  }
  for (int p : region) taken[std::size_t(p)] = 2;  // refused: seeds and joins projection charts only
  return std::nullopt;
}

}  // namespace

std::vector<ChartGroup> groupCharts(const Scene& scene, double angleDegrees, ChartMap map) {
  const auto& polys = scene.polygons();
  std::vector<ChartGroup> out;
  if (angleDegrees < 0) {
    for (std::size_t p = 0; p < polys.size(); ++p)
      out.push_back({{int(p)}, polys[p].normal, true, {polys[p].vertices}, {int(p)}, {}});
    return out;
  }
  const Welding w = weldVertices(scene);
  const auto neighbours = edgeNeighbours(w);
  const double angle = std::min(angleDegrees, kMaxChartAngle) * M_PI / 180;
  std::vector<char> taken(polys.size(), 0);  // 1: in a chart; 2: refused by LSCM, free for projection
  std::vector<int> stamp(polys.size() + 1, 0);
  for (std::size_t p = 0; p < polys.size(); ++p) {
    if (taken[p] == 1) continue;
    if (map == ChartMap::Lscm && angle > 0 && taken[p] == 0)
      if (auto g = lscmChart(scene, w, neighbours, int(p), angle, taken, stamp)) {
        out.push_back(std::move(*g));
        continue;
      }
    ChartGroup g = growChart(scene, neighbours, int(p), angle, taken);
    Poly3 outline = g.planar && g.polygons.size() > 1 ? mergedOutline(scene, w, g.polygons, g.axis) : Poly3{};
    if (!outline.empty())
      g.parts = {outline}, g.partPolygon = {g.polygons[0]};
    else
      for (int m : g.polygons) g.parts.push_back(polys[std::size_t(m)].vertices), g.partPolygon.push_back(m);
    out.push_back(std::move(g));
  }
  return out;
}

std::vector<ChartGroup> chartGroups(const Scene& scene, double angleDegrees, UvSource uv) {
  if (uv == UvSource::Input) return inputUvCharts(scene);
  return groupCharts(scene, angleDegrees, uv == UvSource::Projection ? ChartMap::Projection : ChartMap::Lscm);
}

}  // namespace hemirad
