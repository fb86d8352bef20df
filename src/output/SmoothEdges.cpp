#include "src/output/SmoothEdges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "src/scene/Contacts.h"
#include "src/scene/Welding.h"

namespace hemirad {

namespace {

bool alike(const Scene& scene, const ScenePolygon& p, const ScenePolygon& q) {
  const Material &m = scene.materials[p.material], &n = scene.materials[q.material];
  return m.reflectance == n.reflectance && m.emission == n.emission &&
         glm::dot(p.normal, q.normal) >= std::cos(kStitchAngle * M_PI / 180);
}

// Polygon pairs sharing an edge, with the edge as the first has it.
std::vector<SmoothEdge> sharedEdges(const Scene& scene) {
  const Welding w = weldVertices(scene);
  std::vector<SmoothEdge> out;
  for (auto& [edge, ps] : polygonsByEdge(w))
    if (ps.size() == 2) {
      const std::size_t p = std::size_t(ps[0]);
      const Poly3& v = scene.polygons()[p].vertices;
      glm::dvec3 a(0.0), b(0.0);
      for (std::size_t i = 0; i < v.size(); ++i)
        if (w.ids[p][i] == edge.first)
          a = v[i];
        else if (w.ids[p][i] == edge.second)
          b = v[i];
      out.push_back({ps[0], ps[1], a, b});
    }
  return out;
}

// The scene's creases (discontinuity lines, Scene::creases: light jumps there), bucketed by the
// cells their boxes cover, so a seam meets only the creases around its middle.
class Creases {
 public:
  explicit Creases(const Scene& scene) : scene_(scene) {
    if (scene.creases.empty()) return;
    lo_ = scene.boundsMin();
    const double diag = glm::length(scene.boundsMax() - lo_);
    tolerance_ = kContactTolerance * diag, cell_ = diag / 64;
    for (std::size_t i = 0; i < scene.creases.size(); ++i) {
      const auto& c = scene.creases[i];
      const glm::ivec3 a = cellOf(glm::min(c[0], c[1]) - tolerance_), b = cellOf(glm::max(c[0], c[1]) + tolerance_);
      for (int z = a.z; z <= b.z; ++z)
        for (int y = a.y; y <= b.y; ++y)
          for (int x = a.x; x <= b.x; ++x) cells_[key({x, y, z})].push_back(int(i));
    }
  }
  // Whether edge a-b runs along a crease.
  bool along(glm::dvec3 a, glm::dvec3 b) const {
    if (cells_.empty()) return false;
    const auto it = cells_.find(key(cellOf(0.5 * (a + b))));
    if (it == cells_.end()) return false;
    auto near = [&](const std::array<glm::dvec3, 2>& c, glm::dvec3 x) {
      const glm::dvec3 d = c[1] - c[0];
      const double t = std::clamp(glm::dot(x - c[0], d) / glm::dot(d, d), 0.0, 1.0);
      return glm::length(x - (c[0] + t * d)) <= tolerance_;
    };
    return std::any_of(it->second.begin(), it->second.end(), [&](int i) {
      return near(scene_.creases[std::size_t(i)], a) && near(scene_.creases[std::size_t(i)], b);
    });
  }

 private:
  glm::ivec3 cellOf(glm::dvec3 p) const { return glm::ivec3(glm::floor((p - lo_) / cell_)); }
  static std::uint64_t key(glm::ivec3 c) {
    return std::uint64_t(std::uint32_t(c.x + (1 << 20)) & 0x1FFFFF) << 42 |
           std::uint64_t(std::uint32_t(c.y + (1 << 20)) & 0x1FFFFF) << 21 | (std::uint32_t(c.z + (1 << 20)) & 0x1FFFFF);
  }
  const Scene& scene_;
  glm::dvec3 lo_{0};
  double tolerance_ = 0, cell_ = 1;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

}  // namespace

std::vector<SmoothEdge> smoothEdges(const Scene& scene) {
  const Creases creases(scene);
  std::vector<SmoothEdge> out;
  for (const SmoothEdge& e : sharedEdges(scene))
    if (alike(scene, scene.polygons()[std::size_t(e.p)], scene.polygons()[std::size_t(e.q)]) &&
        !creases.along(e.a, e.b))
      out.push_back(e);
  return out;
}

}  // namespace hemirad
