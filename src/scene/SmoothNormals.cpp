#include "src/scene/SmoothNormals.h"

#include <algorithm>
#include <cmath>

#include "src/scene/Welding.h"

namespace hemirad {

namespace {

// The angle of p's corner at vertex i (its weight in the vertex's normal).
double cornerAngle(const Poly3& p, std::size_t i) {
  const glm::dvec3 v = p[i], a = p[(i + p.size() - 1) % p.size()] - v, b = p[(i + 1) % p.size()] - v;
  const double la = glm::length(a), lb = glm::length(b);
  return la > 0 && lb > 0 ? std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0, 1.0)) : 0.0;
}

}  // namespace

std::vector<std::vector<glm::dvec3>> smoothVertexNormals(const Scene& scene, double angleDegrees) {
  const double cosAngle = std::cos(std::clamp(angleDegrees, 0.0, 90.0) * M_PI / 180);
  const Welding w = weldVertices(scene);
  std::vector<std::vector<std::pair<int, std::size_t>>> corners(w.position.size());  // welded vertex: (polygon, corner)
  const auto& polys = scene.polygons();
  for (std::size_t p = 0; p < polys.size(); ++p)
    for (std::size_t i = 0; i < polys[p].vertices.size(); ++i) corners[std::size_t(w.ids[p][i])].push_back({int(p), i});
  std::vector<std::vector<glm::dvec3>> out(polys.size());
  for (std::size_t p = 0; p < polys.size(); ++p) {
    const ScenePolygon& P = polys[p];
    for (std::size_t i = 0; i < P.vertices.size(); ++i) {
      glm::dvec3 sum(0.0);
      for (auto [q, j] : corners[std::size_t(w.ids[p][i])]) {
        const ScenePolygon& Q = polys[std::size_t(q)];
        if (Q.object != P.object || Q.material != P.material || glm::dot(Q.normal, P.normal) < cosAngle) continue;
        sum += cornerAngle(Q.vertices, j) * Q.normal;
      }
      out[p].push_back(glm::length(sum) > 0 ? glm::normalize(sum) : P.normal);
    }
  }
  return out;
}

glm::dvec3 smoothNormalAt(const ScenePolygon& poly, const std::vector<glm::dvec3>& vertexNormals, glm::dvec3 p) {
  const Poly3& v = poly.vertices;
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const glm::dvec3 a = v[0], b = v[i], c = v[i + 1];
    const double whole = glm::dot(glm::cross(b - a, c - a), poly.normal);
    if (!(std::abs(whole) > 0)) continue;
    const double u = glm::dot(glm::cross(c - b, p - b), poly.normal) / whole,  // weight of a
        w = glm::dot(glm::cross(a - c, p - c), poly.normal) / whole;           // weight of b
    const double x = 1 - u - w;                                                // weight of c
    if (u < -1e-9 || w < -1e-9 || x < -1e-9) continue;
    const glm::dvec3 n = u * vertexNormals[0] + w * vertexNormals[i] + x * vertexNormals[i + 1];
    return glm::length(n) > 0 ? glm::normalize(n) : poly.normal;
  }
  return poly.normal;
}

}  // namespace hemirad
