#include "src/scene/Charts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <map>

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

// A curved chart must not fold over itself: the candidate's projection may not overlap a
// member's (beyond rounding), or two surfaces would share texels.
bool overlapsMembers(const PlaneFrame& f, const Scene& scene, const std::vector<int>& members, int candidate) {
  const Poly2 c = projectAlong(f, scene.polygons()[std::size_t(candidate)].vertices);
  const double tiny = 1e-9 * std::abs(signedArea(c));
  glm::dvec2 lo(1e300), hi(-1e300);
  for (auto& v : c) lo = glm::min(lo, v), hi = glm::max(hi, v);
  for (int m : members) {
    const Poly2 p = projectAlong(f, scene.polygons()[std::size_t(m)].vertices);
    glm::dvec2 plo(1e300), phi(-1e300);
    for (auto& v : p) plo = glm::min(plo, v), phi = glm::max(phi, v);
    if (glm::any(glm::lessThan(phi, lo)) || glm::any(glm::lessThan(hi, plo))) continue;
    Poly2 both = clipConvexPolygons(c, p);
    if (both.size() >= 3 && std::abs(signedArea(both)) > tiny) return true;
  }
  return false;
}

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
    glm::dvec3 a = w.position[std::size_t(loop[(i + loop.size() - 1) % loop.size()])], b = w.position[std::size_t(loop[i])],
               c = w.position[std::size_t(loop[(i + 1) % loop.size()])];
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
  std::deque<int> queue{seed};
  taken[std::size_t(seed)] = 1;
  while (!queue.empty()) {
    const int p = queue.front();
    queue.pop_front();
    g.polygons.push_back(p);
    for (int q : neighbours[std::size_t(p)]) {
      if (taken[std::size_t(q)] || !joins(scene, seed, q, cosAngle)) continue;
      const bool coplanar = glm::dot(scene.polygons()[std::size_t(q)].normal, g.axis) > cosPlanar &&
                            std::abs(glm::dot(scene.polygons()[std::size_t(q)].vertices[0] - f.origin, g.axis)) <=
                                1e-9 * (1 + glm::length(scene.polygons()[std::size_t(q)].vertices[0] - f.origin));
      if (!coplanar && overlapsMembers(f, scene, g.polygons, q)) continue;
      g.planar = g.planar && coplanar;
      taken[std::size_t(q)] = 1;
      queue.push_back(q);
    }
  }
  return g;
}

}  // namespace

std::vector<ChartGroup> groupCharts(const Scene& scene, double angleDegrees) {
  const auto& polys = scene.polygons();
  std::vector<ChartGroup> out;
  if (angleDegrees < 0) {
    for (std::size_t p = 0; p < polys.size(); ++p)
      out.push_back({{int(p)}, polys[p].normal, true, {polys[p].vertices}, {int(p)}});
    return out;
  }
  const Welding w = weldVertices(scene);
  const auto neighbours = edgeNeighbours(w);
  const double angle = std::min(angleDegrees, kMaxChartAngle) * M_PI / 180;
  std::vector<char> taken(polys.size(), 0);
  for (std::size_t p = 0; p < polys.size(); ++p) {
    if (taken[p]) continue;
    ChartGroup g = growChart(scene, neighbours, int(p), angle, taken);
    Poly3 outline = g.planar && g.polygons.size() > 1 ? mergedOutline(scene, w, g.polygons, g.axis) : Poly3{};
    if (!outline.empty()) g.parts = {outline}, g.partPolygon = {g.polygons[0]};
    else
      for (int m : g.polygons) g.parts.push_back(polys[std::size_t(m)].vertices), g.partPolygon.push_back(m);
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace hemirad
