#include "src/scene/Lscm.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Two_vertices_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "src/base/MinAreaRect.h"

namespace hemirad {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using Halfedge = Mesh::Halfedge_index;
namespace SMP = CGAL::Surface_mesh_parameterization;

// The mesh of `triangles`, or false when it is not a connected manifold disc: every face added
// (no edge of three faces, none oriented against its neighbour), one boundary loop through each
// of its vertices once, one component, Euler characteristic V - E + F = 1.
bool buildDisc(const std::vector<glm::dvec3>& positions, const std::vector<std::array<int, 3>>& triangles, Mesh& m,
               Halfedge& border) {
  for (const glm::dvec3& p : positions) m.add_vertex({p.x, p.y, p.z});
  for (const auto& t : triangles)
    if (m.add_face(Vertex(t[0]), Vertex(t[1]), Vertex(t[2])) == Mesh::null_face()) return false;
  std::vector<char> onLoop(m.number_of_halfedges(), 0), borderIn(m.number_of_vertices(), 0);
  int loops = 0;
  for (Halfedge h : m.halfedges()) {
    if (!m.is_border(h) || onLoop[h.idx()]) continue;
    ++loops, border = h;
    for (Halfedge g = h; !onLoop[g.idx()]; g = m.next(g)) {
      onLoop[g.idx()] = 1;
      if (borderIn[m.target(g).idx()]++) return false;  // a pinched vertex: two fans touch there
    }
  }
  const long euler = long(m.number_of_vertices()) - long(m.number_of_edges()) + long(m.number_of_faces());
  if (loops != 1 || euler != 1) return false;
  std::vector<char> seen(m.number_of_faces(), 0);
  std::vector<Mesh::Face_index> stack{*m.faces().begin()};
  seen[stack.back().idx()] = 1;
  std::size_t reached = 1;
  while (!stack.empty()) {
    const Halfedge first = m.halfedge(stack.back());
    stack.pop_back();
    Halfedge h = first;
    do {
      const Mesh::Face_index f = m.face(m.opposite(h));
      if (f != Mesh::null_face() && !seen[f.idx()]) seen[f.idx()] = 1, ++reached, stack.push_back(f);
      h = m.next(h);
    } while (h != first);
  }
  return reached == m.number_of_faces();
}

// Whether two segments ab and cd meet (touching counts).
bool segmentsMeet(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
  auto orient = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
    const double v = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    return (v > 0) - (v < 0);
  };
  auto within = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {  // r on line pq: within its box
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && within(a, b, c)) || (o2 == 0 && within(a, b, d)) || (o3 == 0 && within(c, d, a)) ||
         (o4 == 0 && within(c, d, b));
}

// Whether the closed loop `loop` crosses or touches itself (segments not next to each other).
// Segments are bucketed in a grid of about their mean length, so a loop of n segments costs ~n.
bool selfIntersects(const std::vector<glm::dvec2>& loop) {
  const std::size_t n = loop.size();
  glm::dvec2 lo(1e300), hi(-1e300);
  double length = 0;
  for (std::size_t i = 0; i < n; ++i)
    lo = glm::min(lo, loop[i]), hi = glm::max(hi, loop[i]), length += glm::length(loop[(i + 1) % n] - loop[i]);
  const double cell = std::max({length / double(n), (hi.x - lo.x) / 1024, (hi.y - lo.y) / 1024, 1e-300});
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = loop[i], b = loop[(i + 1) % n];
    const glm::ivec2 c0((glm::min(a, b) - lo) / cell), c1((glm::max(a, b) - lo) / cell);
    for (int y = c0.y; y <= c1.y; ++y)
      for (int x = c0.x; x <= c1.x; ++x) {
        auto& bucket = grid[std::uint64_t(std::uint32_t(x)) << 32 | std::uint32_t(y)];
        for (std::uint32_t j : bucket) {
          const std::size_t gap = (i - j + n) % n;
          if (gap != 1 && gap != n - 1 && segmentsMeet(a, b, loop[j], loop[(j + 1) % n])) return true;
        }
        bucket.push_back(std::uint32_t(i));
      }
  }
  return false;
}

// The boundary loop's vertices, in order from `border`.
std::vector<Vertex> boundaryLoop(const Mesh& m, Halfedge border) {
  std::vector<Vertex> out;
  Halfedge h = border;
  do out.push_back(m.target(h)), h = m.next(h);
  while (h != border);
  return out;
}

// The singular values (largest, smallest) of the map of 3D triangle t onto 2D triangle q.
glm::dvec2 singularValues(const std::array<glm::dvec3, 3>& t, const Poly2& q) {
  const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const glm::dvec3 x = glm::normalize(e1), y = glm::normalize(glm::cross(glm::cross(e1, e2), e1));
  const double p11 = glm::length(e1), p12 = glm::dot(e2, x), p22 = glm::dot(e2, y);  // P = [p11 p12; 0 p22]
  const glm::dvec2 u1 = q[1] - q[0], u2 = q[2] - q[0];
  // J = U P^-1, P^-1 = [1/p11, -p12/(p11 p22); 0, 1/p22].
  const glm::dvec2 c1 = u1 / p11, c2 = (u2 - u1 * (p12 / p11)) / p22;
  const double e = glm::dot(c1, c1) + glm::dot(c2, c2), det = std::abs(c1.x * c2.y - c1.y * c2.x);
  const double s = std::sqrt(e + 2 * det), d = std::sqrt(std::max(e - 2 * det, 0.0));
  return {(s + d) / 2, (s - d) / 2};
}

// Scales (and mirrors, if the map turned the chart over) `uv` so its area is the surface's, and
// grades it: Flipped, Distorted or Mapped.
LscmOutcome grade(const std::vector<std::array<glm::dvec3, 3>>& tris, std::vector<Poly2>& uv, LscmMap& out) {
  double surface = 0, mapped = 0;
  for (std::size_t k = 0; k < tris.size(); ++k)
    surface += area(Poly3(tris[k].begin(), tris[k].end())), mapped += signedArea(uv[k]);
  if (!(std::abs(mapped) > 0) || !std::isfinite(mapped)) return LscmOutcome::SolverFailed;
  const double scale = std::sqrt(surface / std::abs(mapped)), flip = mapped < 0 ? -1 : 1;
  for (Poly2& t : uv)
    for (glm::dvec2& q : t) q = glm::dvec2(flip * q.x, q.y) * scale;
  bool flipped = false;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const double a = area(Poly3(tris[k].begin(), tris[k].end())), r = signedArea(uv[k]) / a;
    flipped = flipped || !(r > 1e-6);
    if (r > 0) out.areaDistortion = std::max({out.areaDistortion, r, 1 / r});
    const glm::dvec2 s = singularValues(tris[k], uv[k]);
    out.anisotropy = std::max(out.anisotropy, s.y > 0 ? s.x / s.y : 1e300);
  }
  if (flipped) return LscmOutcome::Flipped;
  if (out.areaDistortion > kMaxLscmAreaDistortion || out.anisotropy > kMaxLscmAnisotropy) return LscmOutcome::Distorted;
  return LscmOutcome::Mapped;
}

}  // namespace

LscmMap lscmMap(const std::vector<glm::dvec3>& positions, const std::vector<std::array<int, 3>>& triangles) {
  LscmMap out;
  std::vector<std::array<glm::dvec3, 3>> tris;
  for (const auto& t : triangles) {
    tris.push_back({positions[std::size_t(t[0])], positions[std::size_t(t[1])], positions[std::size_t(t[2])]});
    const double edge =
        std::max({glm::length(tris.back()[1] - tris.back()[0]), glm::length(tris.back()[2] - tris.back()[1]),
                  glm::length(tris.back()[0] - tris.back()[2])});
    // A sliver (area under 1e-9 of its longest edge's square) has no conformal shape to keep.
    if (!(area(Poly3(tris.back().begin(), tris.back().end())) > 1e-9 * edge * edge)) {
      out.outcome = LscmOutcome::Degenerate;
      return out;
    }
  }
  Mesh m;
  Halfedge border;
  if (triangles.empty() || !buildDisc(positions, triangles, m, border)) return out;
  auto uvMap = m.add_property_map<Vertex, Kernel::Point_2>("v:uv").first;
  using Parameterizer = SMP::LSCM_parameterizer_3<Mesh, SMP::Two_vertices_parameterizer_3<Mesh>>;
  SMP::Error_code solved = SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  try {
    solved = SMP::parameterize(m, Parameterizer(), border, uvMap);
  } catch (const CGAL::Failure_exception&) {  // a checked build's precondition: the chart stays projected
  }
  if (solved != SMP::OK) {
    out.outcome = LscmOutcome::SolverFailed;
    return out;
  }
  std::vector<Poly2> uv;
  for (const auto& t : triangles) {
    Poly2& q = uv.emplace_back();
    for (int v : t) q.push_back({uvMap[Vertex(v)].x(), uvMap[Vertex(v)].y()});
  }
  out.outcome = grade(tris, uv, out);
  if (out.outcome != LscmOutcome::Mapped) return out;
  std::vector<glm::dvec2> at(positions.size()), loop;  // per vertex, its scaled chart point
  for (std::size_t k = 0; k < triangles.size(); ++k)
    for (int i = 0; i < 3; ++i) at[std::size_t(triangles[k][std::size_t(i)])] = uv[k][std::size_t(i)];
  for (Vertex v : boundaryLoop(m, border)) loop.push_back(at[v.idx()]);
  if (selfIntersects(loop)) {
    out.outcome = LscmOutcome::Overlapping;
    return out;
  }
  // Laid along its minimum-area rectangle, as projection charts are (Atlas.cpp's chartFrame): the
  // solver's arbitrary orientation would leave its grid's corners empty.
  const MinAreaRect rect = minAreaRect(at);
  double mapped = 0;
  for (const Poly2& t : uv) mapped += signedArea(t);
  if (mapped < kMinLscmFill * rect.area) {
    out.outcome = LscmOutcome::Ragged;
    return out;
  }
  const glm::dvec2 a = rect.axis;
  for (Poly2& t : uv)
    for (glm::dvec2& q : t) q = glm::dvec2(glm::dot(q, a), a.x * q.y - a.y * q.x);
  out.uv = std::move(uv);
  return out;
}

}  // namespace hemirad
