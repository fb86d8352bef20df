// Exact form factors in double: the CPU reference, and the twin of shaders/formfactor.glsl (the
// GPU gather's kernel, same clip and atan2 contour sum; tests/HemisphereTest compares them).
#pragma once
#include <functional>
#include <glm/glm.hpp>
#include <vector>

namespace hemirad::cpu {

using Polygon = std::vector<glm::dvec3>;

// Whether a receiver at pr (normal nr) and a shooter at ps (normal ns) face each other. Cosines
// under 1e-6 count as coplanar: rounding must not make neighbours on one plane exchange light.
inline bool facing(const glm::dvec3& ps, const glm::dvec3& ns, const glm::dvec3& pr, const glm::dvec3& nr) {
  glm::dvec3 d = pr - ps;
  double len = glm::length(d);
  return glm::dot(d, ns) > 1e-6 * len && glm::dot(-d, nr) > 1e-6 * len;
}

// Differential area at p (unit normal n) to a planar polygon, by Lambert's contour formula
// F = (1 / 2 pi) sum_i theta_i n . (R_i x R_i+1) / |R_i x R_i+1|, after clipping the polygon to the
// half-space in front of p (the horizon). Only the polygon's front side (counter-clockwise around
// `frontNormal`) emits: a p behind its plane gets 0. Unoccluded.
double pointToPolygon(const glm::dvec3& p, const glm::dvec3& n, const Polygon& polygon, const glm::dvec3& frontNormal);

// Visibility between a receiver point and a point on the shooter: true if unoccluded.
using VisibleFn = std::function<bool(const glm::dvec3& shooterPoint)>;

struct ElementFormFactor {
  double value = 0;  // form factor from dA at p to the shooter element, occlusion included
  double bound = 0;  // |error| bound: the form factor of the sub-cells on a visibility change
};

// Point p to a (convex, planar) shooter element with occlusion. If its centre and corners are
// all visible from p the element is taken as unoccluded and the result is exact (bound 0); else it
// is split into `strata` x `strata` cells (along its two longest directions), each cell exact times
// the visibility of its centroid; the bound sums the cells whose visibility differs from a
// neighbour's, which is where the stratified answer can be wrong.
ElementFormFactor pointToElement(const glm::dvec3& p, const glm::dvec3& n, const Polygon& element,
                                 const glm::dvec3& frontNormal, const VisibleFn& visible, int strata = 4);

// Gauss-Legendre nodes and weights on [0, 1].
void gaussLegendre(int count, std::vector<double>& nodes, std::vector<double>& weights);

// Area-averaged form factor from the rectangle (origin, u, v, w, h: front u x v) to `target`:
// (1/A) integral over the rectangle of pointToPolygon. Quadrature graded geometrically toward the
// rectangle's edge at v = 0 (where a neighbour sharing that edge makes the integrand singular).
double rectangleToPolygon(const glm::dvec3& origin, const glm::dvec3& u, const glm::dvec3& v, double w, double h,
                          const Polygon& target, const glm::dvec3& targetNormal);

}  // namespace hemirad::cpu
