#include "src/scene/Welding.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hemirad {

Welding weldVertices(const Scene& scene) {
  const double q = 1e-9 * std::max(glm::length(scene.boundsMax() - scene.boundsMin()), 1e-300);
  std::map<std::array<long long, 3>, int> index;
  Welding w;
  for (const ScenePolygon& p : scene.polygons()) {
    std::vector<int>& ids = w.ids.emplace_back();
    for (const glm::dvec3& v : p.vertices) {
      const std::array<long long, 3> k{std::llround(v.x / q), std::llround(v.y / q), std::llround(v.z / q)};
      auto [it, added] = index.emplace(k, int(w.position.size()));
      if (added) w.position.push_back(v);
      ids.push_back(it->second);
    }
  }
  return w;
}

std::map<WeldedEdge, std::vector<int>> polygonsByEdge(const Welding& w) {
  std::map<WeldedEdge, std::vector<int>> byEdge;
  for (std::size_t p = 0; p < w.ids.size(); ++p)
    for (std::size_t i = 0; i < w.ids[p].size(); ++i) {
      const int a = w.ids[p][i], b = w.ids[p][(i + 1) % w.ids[p].size()];
      if (a != b) byEdge[{std::min(a, b), std::max(a, b)}].push_back(int(p));
    }
  return byEdge;
}

}  // namespace hemirad
