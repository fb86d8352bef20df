#include "src/scene/InputUv.h"

#include <array>
#include <cmath>
#include <map>
#include <numeric>

#include "src/base/Error.h"

namespace hemirad {

namespace {

// Fails unless every polygon has a UV per vertex.
void requireUvs(const Scene& scene) {
  const auto& polys = scene.polygons();
  std::size_t missing = 0, first = 0;
  for (std::size_t p = polys.size(); p-- > 0;)
    if (p >= scene.lightmapUv.size() || scene.lightmapUv[p].size() != polys[p].vertices.size()) ++missing, first = p;
  if (missing)
    fail(
        "{}: --uv input needs lightmap UVs (glTF TEXCOORD_1, OBJ vt) on every face; {} of {} polygons have none "
        "(the first: polygon {}); use --uv auto",
        scene.path, missing, polys.size(), first);
}

// Scene units per UV unit: sqrt(surface area / UV area) over every polygon (fanned).
double uvScale(const Scene& scene) {
  double surface = 0, uvArea = 0;
  for (std::size_t p = 0; p < scene.polygons().size(); ++p)
    surface += scene.polygons()[p].area, uvArea += std::abs(signedArea(scene.lightmapUv[p]));
  if (!(uvArea > 0)) fail("{}: --uv input: the lightmap UVs (TEXCOORD_1) cover no area", scene.path);
  return std::sqrt(surface / uvArea);
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
  return i;
}

// Per polygon: its island's root. Polygons sharing an edge (both ends' position and UV) of
// one material and object join.
std::vector<int> islands(const Scene& scene) {
  using Corner = std::array<double, 5>;  // position, UV
  std::map<std::array<double, 12>, int> edges;
  std::vector<int> parent(scene.polygons().size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t p = 0; p < parent.size(); ++p) {
    const ScenePolygon& poly = scene.polygons()[p];
    auto corner = [&](std::size_t i) {
      const glm::dvec3 x = poly.vertices[i];
      const glm::dvec2 u = scene.lightmapUv[p][i];
      return Corner{x.x, x.y, x.z, u.x, u.y};
    };
    for (std::size_t i = 0; i < poly.vertices.size(); ++i) {
      Corner a = corner(i), b = corner((i + 1) % poly.vertices.size());
      if (b < a) std::swap(a, b);
      std::array<double, 12> key{double(poly.material), double(poly.object)};
      std::copy(a.begin(), a.end(), key.begin() + 2), std::copy(b.begin(), b.end(), key.begin() + 7);
      auto [it, added] = edges.emplace(key, int(p));
      if (!added) parent[std::size_t(findRoot(parent, int(p)))] = findRoot(parent, it->second);
    }
  }
  for (std::size_t p = 0; p < parent.size(); ++p) parent[p] = findRoot(parent, int(p));
  return parent;
}

// Island `members` as a chart: fanned triangles, UVs times `scale`, mirrored if the input mirrors it.
ChartGroup islandChart(const Scene& scene, const std::vector<int>& members, double scale) {
  ChartGroup g;
  g.polygons = members;
  const ScenePolygon& seed = scene.polygons()[std::size_t(members.front())];
  g.axis = seed.normal;
  double signedUv = 0;
  for (int m : members) {
    const ScenePolygon& p = scene.polygons()[std::size_t(m)];
    const Poly2& uv = scene.lightmapUv[std::size_t(m)];
    g.planar = g.planar && glm::dot(p.normal, seed.normal) > std::cos(kCoplanarRadians) &&
               std::abs(glm::dot(p.vertices[0] - seed.vertices[0], seed.normal)) <=
                   1e-9 * (1 + glm::length(p.vertices[0] - seed.vertices[0]));
    for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
      g.parts.push_back({p.vertices[0], p.vertices[k], p.vertices[k + 1]});
      g.uv.push_back({uv[0] * scale, uv[k] * scale, uv[k + 1] * scale});
      g.partPolygon.push_back(m);
      signedUv += signedArea(g.uv.back());
    }
  }
  if (signedUv < 0)
    for (Poly2& t : g.uv)
      for (glm::dvec2& q : t) q.x = -q.x;
  for (std::size_t k = 0; k < g.parts.size(); ++k)
    if (!(signedArea(g.uv[k]) > kMinUvAreaRatio * area(g.parts[k])))
      fail(
          "{}: --uv input: polygon {} has a degenerate or folded UV triangle (UV area {:.3g} of its surface's); "
          "lightmap UVs must be one-to-one",
          scene.path, g.partPolygon[k], signedArea(g.uv[k]) / area(g.parts[k]));
  return g;
}

}  // namespace

std::vector<ChartGroup> inputUvCharts(const Scene& scene) {
  requireUvs(scene);
  const double scale = uvScale(scene);
  const std::vector<int> root = islands(scene);
  std::vector<int> order(root.size(), -1);  // root -> island, in order of first polygon
  std::vector<std::vector<int>> members;
  for (std::size_t p = 0; p < root.size(); ++p) {
    int& island = order[std::size_t(root[p])];
    if (island < 0) island = int(members.size()), members.emplace_back();
    members[std::size_t(island)].push_back(int(p));
  }
  std::vector<ChartGroup> out;
  for (const auto& m : members) out.push_back(islandChart(scene, m, scale));
  return out;
}

}  // namespace hemirad
