#include "src/scene/ItemMesh.h"

#include <array>
#include <cstring>
#include <map>

namespace hemirad {

namespace {
using Tri = std::array<glm::dvec3, 3>;

glm::dvec3 midpoint(const glm::dvec3& a, const glm::dvec3& b) {
  // Order-independent, so both triangles on an edge produce the bitwise-same point.
  return (a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.z < b.z)))) ? (a + b) * 0.5 : (b + a) * 0.5;
}

void split(const Tri& t, int level, std::uint32_t polygon, std::vector<ItemVertex>& out) {
  if (level == 0) {
    for (auto& v : t) out.push_back({float(v.x), float(v.y), float(v.z), polygon});
    return;
  }
  glm::dvec3 ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
  split({t[0], ab, ca}, level - 1, polygon, out);
  split({ab, t[1], bc}, level - 1, polygon, out);
  split({ca, bc, t[2]}, level - 1, polygon, out);
  split({ab, bc, ca}, level - 1, polygon, out);
}
}  // namespace

std::vector<ItemVertex> buildItemMesh(const Scene& scene, int level) {
  std::vector<ItemVertex> out;
  out.reserve(3 * itemTriangleCount(scene, level));
  for (std::uint32_t id = 0; id < scene.occluderCount(); ++id) {
    if (!scene.drawn(id)) continue;
    const Poly3& v = scene.occluder(id).vertices;
    for (size_t k = 1; k + 1 < v.size(); ++k) split({v[0], v[k], v[k + 1]}, level, id, out);  // convex: a fan
  }
  return out;
}

IndexedItemMesh indexItemMesh(const std::vector<ItemVertex>& triangles) {
  IndexedItemMesh mesh;
  std::map<std::array<std::uint32_t, 4>, std::uint32_t> index;
  for (const ItemVertex& v : triangles) {
    std::array<std::uint32_t, 4> key;
    std::memcpy(key.data(), &v, sizeof key);
    auto [it, added] = index.try_emplace(key, std::uint32_t(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(v);
    mesh.indices.push_back(it->second);
  }
  return mesh;
}

}  // namespace hemirad
