#include "src/scene/FaceRepair.h"

#include <fmt/format.h>

#include <algorithm>

namespace hemirad {

namespace {
constexpr double kPlanarTolerance = 1e-4;  // of the polygon's size

double polygonSize(const Poly3& poly) {
  double size = 0;
  for (auto& v : poly) size = std::max(size, glm::length(v - poly.front()));
  return size;
}

bool hasArea(const Poly3& poly, const glm::dvec3& normal) {
  const double size = polygonSize(poly);
  return poly.size() >= 3 && glm::length(normal) > 1e-12 * size * size;
}

// The shortest cycle `poly` repeats (`f 1 2 3 4 1 2 3 4`: 1 2 3 4), or `poly` itself. A repeated
// cycle passes the convexity test corner by corner, but its Newell area counts every lap: an
// emitter of twice its area creates energy (convergence below 0).
Poly3 singleCycle(const Poly3& poly) {
  const std::size_t n = poly.size();
  for (std::size_t period = 3; period <= n / 2; ++period) {
    if (n % period) continue;
    bool repeats = true;
    for (std::size_t k = period; k < n && repeats; ++k) repeats = poly[k] == poly[k - period];
    if (repeats) return Poly3(poly.begin(), poly.begin() + std::ptrdiff_t(period));
  }
  return poly;
}
}  // namespace

bool isPlanarConvex(const Poly3& poly) {
  glm::dvec3 normal = poly.size() >= 3 ? newellNormal(poly) : glm::dvec3(0.0);
  return hasArea(poly, normal) && planarityError(poly) <= kPlanarTolerance * polygonSize(poly) &&
         isConvex(poly, normal);
}

void addFace(Scene& scene, const Poly3& face, int material, int object, const FaceSite& where) {
  const Poly3 poly = singleCycle(face);
  if (poly.size() < face.size())
    scene.warnings.push_back({where(), "face repeats its vertex cycle; read as the single cycle"});
  glm::dvec3 normal = poly.size() >= 3 ? newellNormal(poly) : glm::dvec3(0.0);
  if (!hasArea(poly, normal)) {
    scene.warnings.push_back({where(), "degenerate face with zero area skipped"});
    return;
  }
  bool planar = planarityError(poly) <= kPlanarTolerance * polygonSize(poly);
  if (planar && isConvex(poly, normal)) {
    scene.addPolygon(poly, material, object);
    return;
  }
  const char* shape = planar ? "non-convex" : "non-planar";
  scene.warnings.push_back({where(), fmt::format("{} polygon split into triangles", shape)});
  std::vector<int> tris = triangulate(poly, normal);
  for (size_t t = 0; t < tris.size(); t += 3)
    scene.addPolygon({poly[tris[t]], poly[tris[t + 1]], poly[tris[t + 2]]}, material, object);
}

}  // namespace hemirad
