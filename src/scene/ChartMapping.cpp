#include "src/scene/ChartMapping.h"

#include <algorithm>

namespace hemirad {

namespace {

// Barycentric coordinates of q in the 2D triangle t.
glm::dvec3 barycentric(const Poly2& t, glm::dvec2 q) {
  const glm::dvec2 e1 = t[1] - t[0], e2 = t[2] - t[0], d = q - t[0];
  const double det = e1.x * e2.y - e1.y * e2.x;
  const double b1 = (d.x * e2.y - d.y * e2.x) / det, b2 = (e1.x * d.y - e1.y * d.x) / det;
  return {1 - b1 - b2, b1, b2};
}

// Barycentric coordinates of p, taken into the plane of the 3D triangle t.
glm::dvec3 barycentric(const Poly3& t, const glm::dvec3& p) {
  const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0], d = p - t[0];
  const double d11 = glm::dot(e1, e1), d12 = glm::dot(e1, e2), d22 = glm::dot(e2, e2);
  const double d1 = glm::dot(d, e1), d2 = glm::dot(d, e2), det = d11 * d22 - d12 * d12;
  const double b1 = (d22 * d1 - d12 * d2) / det, b2 = (d11 * d2 - d12 * d1) / det;
  return {1 - b1 - b2, b1, b2};
}

}  // namespace

glm::dvec3 liftTriangle(const Poly3& tri, const Poly2& uv, glm::dvec2 q) {
  const glm::dvec3 b = barycentric(uv, q);
  return b.x * tri[0] + b.y * tri[1] + b.z * tri[2];
}

Poly2 ChartMapping::partInChart(const Poly3& part, std::size_t k) const {
  if (uvMapped()) return uv[k];
  Poly2 out;
  for (auto& v : part) out.push_back(frame.project(v));
  return out;
}

glm::dvec2 ChartMapping::toChart(const Poly3& part, std::size_t k, const glm::dvec3& p) const {
  if (!uvMapped()) return frame.project(p);
  const glm::dvec3 b = barycentric(part, p);
  return b.x * uv[k][0] + b.y * uv[k][1] + b.z * uv[k][2];
}

// A projection chart: chart point q moved along the axis onto the plane of polygon `on` (a
// planar chart's pieces lie in the frame's plane already).
glm::dvec3 ChartMapping::toSurface(const Poly3& part, std::size_t k, const ScenePolygon& on, glm::dvec2 q) const {
  if (uvMapped()) return liftTriangle(part, uv[k], q);
  glm::dvec3 p = frame.lift(q);
  return planar ? p : p + frame.n * (glm::dot(on.vertices[0] - p, on.normal) / glm::dot(frame.n, on.normal));
}

double ChartMapping::surfaceArea(const Poly3& part, std::size_t k, const ScenePolygon& on, double chartArea) const {
  if (uvMapped()) return chartArea * (area(part) / signedArea(uv[k]));
  return chartArea / (planar ? 1.0 : glm::dot(frame.n, on.normal));
}

double ChartMapping::inside(const Poly3& part, std::size_t, const glm::dvec3& p) const {
  const glm::dvec3 b = barycentric(part, p);
  return std::min({b.x, b.y, b.z});
}

}  // namespace hemirad
