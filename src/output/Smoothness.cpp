#include "src/output/Smoothness.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace hemirad {

namespace {

// The points' distance from an edge, in texels: small, so light's own slope adds little to a jump
// (a seam's step does not shrink with it; a step within a chart's bilinear lookup does).
constexpr double kDelta = 1.0 / 16;

double lum(const Atlas& atlas, const std::vector<glm::vec4>& values, int polygon, glm::dvec3 p) {
  return luminance(glm::dvec3(atlas.sample(values, polygon, atlas.atlasCoord(polygon, p))));
}

glm::dvec3 centroid(const Poly3& p) {
  glm::dvec3 c(0.0);
  for (const glm::dvec3& v : p) c += v / double(p.size());
  return c;
}

// In polygon f's plane, perpendicular to the edge (direction e, middle m), into f.
glm::dvec3 into(const Poly3& f, glm::dvec3 m, glm::dvec3 e) {
  const glm::dvec3 d = centroid(f) - m, across = d - e * glm::dot(d, e);
  const double length = glm::length(across);
  return length > 0 ? across / length : glm::dvec3(0.0);
}

struct Sums {
  double jump = 0, level = 0;
  void add(double a, double b) { jump += std::abs(a - b), level += 0.5 * (a + b); }
  double relative() const { return level > 0 ? jump / level : 0; }
};

}  // namespace

Smoothness measureSmoothness(const Scene& scene, const Atlas& atlas, const std::vector<SmoothEdge>& edges,
                             const std::vector<glm::vec4>& values) {
  Smoothness out;
  Sums facets, seams, inside;
  for (const SmoothEdge& e : edges) {
    const std::uint32_t cp = atlas.chartOf[std::size_t(e.p)], cq = atlas.chartOf[std::size_t(e.q)];
    if (cp == kNoPolygon || cq == kNoPolygon || e.a == e.b) continue;
    const double delta = kDelta * std::min(atlas.charts[cp].cellSize, atlas.charts[cq].cellSize);
    const Poly3 &P = scene.polygons()[std::size_t(e.p)].vertices, &Q = scene.polygons()[std::size_t(e.q)].vertices;
    const glm::dvec3 middle = 0.5 * (e.a + e.b), dir = glm::normalize(e.b - e.a);
    const glm::dvec3 dp = into(P, middle, dir), dq = into(Q, middle, dir), c = centroid(P);
    const double inP = lum(atlas, values, e.p, c + delta * dp), outP = lum(atlas, values, e.p, c - delta * dp);
    // Points a texel apart along the edge (the middles of equal parts): a long edge weighs as its length.
    const int n = std::max(1, int(std::ceil(glm::length(e.b - e.a) * kDelta / delta)));
    for (int k = 0; k < n; ++k) {
      const glm::dvec3 m = e.a + (e.b - e.a) * ((k + 0.5) / n);
      (cp == cq ? facets : seams).add(lum(atlas, values, e.p, m + delta * dp), lum(atlas, values, e.q, m + delta * dq));
      inside.add(inP, outP);
    }
    ++(cp == cq ? out.facetEdges : out.seams);
  }
  out.facetJump = facets.relative(), out.seamJump = seams.relative(), out.insideJump = inside.relative();
  return out;
}

}  // namespace hemirad
