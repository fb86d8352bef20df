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
}  // namespace

bool isPlanarConvex(const Poly3& poly) {
  glm::dvec3 normal = poly.size() >= 3 ? newellNormal(poly) : glm::dvec3(0.0);
  return hasArea(poly, normal) && planarityError(poly) <= kPlanarTolerance * polygonSize(poly) &&
         isConvex(poly, normal);
}

void addFace(Scene& scene, const Poly3& poly, int material, int object, const FaceSite& where) {
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
