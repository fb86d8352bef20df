// Planar-polygon geometry in double precision: the shapes every texel element is cut from.
#pragma once
#include <glm/glm.hpp>
#include <vector>

namespace hemirad {

using Poly2 = std::vector<glm::dvec2>;
using Poly3 = std::vector<glm::dvec3>;

// Newell's normal: robust for any simple polygon; its length is twice the area.
glm::dvec3 newellNormal(const Poly3& p);
double area(const Poly3& p);
double signedArea(const Poly2& p);
glm::dvec2 centroid(const Poly2& p);  // area centroid; vertex mean if degenerate
// Largest distance of a vertex from the polygon's best plane.
double planarityError(const Poly3& p);
// Convex (no reflex corner) when seen along `normal`.
bool isConvex(const Poly3& p, const glm::dvec3& normal);
// Sutherland–Hodgman clip of a polygon against the box [lo, hi].
Poly2 clipToBox(const Poly2& p, glm::dvec2 lo, glm::dvec2 hi);
// An axis-aligned box; empty (lo above hi) as constructed, until points are added.
struct Box2 {
  glm::dvec2 lo{1e300}, hi{-1e300};
  // Whether it meets the open box (lo, hi): false means clipToBox leaves no area of what it bounds.
  bool meets(glm::dvec2 boxLo, glm::dvec2 boxHi) const {
    return lo.x < boxHi.x && lo.y < boxHi.y && hi.x > boxLo.x && hi.y > boxLo.y;
  }
};
Box2 boundingBox(const Poly2& p);
// Whether p's bounding box meets the open box (lo, hi): a cheap reject before clipToBox.
inline bool overlapsBox(const Poly2& p, glm::dvec2 lo, glm::dvec2 hi) { return boundingBox(p).meets(lo, hi); }
// The parameter range [t0, t1] of a + t (b - a), t in [0, 1], at least `inset` inside convex
// counter-clockwise `poly`; false if none.
bool clipSegment(const Poly2& poly, glm::dvec2 a, glm::dvec2 b, double inset, double& t0, double& t1);
// Ear-clipping triangulation (indices into p) of a simple polygon seen along `normal`.
std::vector<int> triangulate(const Poly3& p, const glm::dvec3& normal);

// Orthonormal frame (u, v, n) of a plane: u along the polygon's longest edge.
struct PlaneFrame {
  glm::dvec3 origin, u, v, n;
  glm::dvec2 project(const glm::dvec3& p) const { return {glm::dot(p - origin, u), glm::dot(p - origin, v)}; }
  glm::dvec3 lift(glm::dvec2 q) const { return origin + q.x * u + q.y * v; }
};
PlaneFrame planeFrame(const Poly3& p, const glm::dvec3& normal);

}  // namespace hemirad
