#include "src/scene/Clusters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace hemirad {

namespace {

// A triangle's chart coordinates fill at most this share of the cell's side: rounding at the
// cell's border never drops a piece.
constexpr double kClusterFill = 0.9;

// Which of six cones around the axes a normal lies in: its dominant axis and sign.
int facing(const glm::dvec3& n) {
  const glm::dvec3 a = glm::abs(n);
  const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  return 2 * axis + (n[axis] < 0);
}

glm::dvec3 areaCentroid(const Scene& scene, const ChartGroup& g) {
  glm::dvec3 sum(0.0);
  double total = 0;
  for (int p : g.polygons) {
    const ScenePolygon& poly = scene.polygons()[std::size_t(p)];
    glm::dvec3 mean(0.0);
    for (const glm::dvec3& v : poly.vertices) mean += v;
    sum += poly.area * mean / double(poly.vertices.size());
    total += poly.area;
  }
  return total > 0 ? sum / total : scene.polygons()[std::size_t(g.polygons.front())].vertices.front();
}

}  // namespace

std::vector<std::vector<int>> smallChartClusters(const Scene& scene, const std::vector<ChartGroup>& groups,
                                                 const std::vector<char>& oneCell, double ts) {
  using Key = std::array<long long, 6>;  // object, material, facing, cube
  std::map<Key, std::vector<int>> byKey;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (!oneCell[i]) continue;
    const ScenePolygon& seed = scene.polygons()[std::size_t(groups[i].polygons.front())];
    const glm::dvec3 cube = glm::floor(areaCentroid(scene, groups[i]) / ts);
    if (!(glm::all(glm::lessThan(glm::abs(cube), glm::dvec3(1e15))))) continue;  // NaN or far past any atlas
    byKey[{seed.object, seed.material, facing(groups[i].axis), (long long)cube.x, (long long)cube.y, (long long)cube.z}]
        .push_back(int(i));
  }
  std::vector<std::vector<int>> sets;
  for (auto& [key, members] : byKey)
    if (members.size() > 1) sets.push_back(std::move(members));
  std::sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) { return a.front() < b.front(); });
  return sets;
}

ChartGroup clusterGroup(const Scene& scene, const std::vector<ChartGroup>& groups, const std::vector<int>& members,
                        double ts) {
  ChartGroup out;
  out.axis = groups[std::size_t(members.front())].axis;
  out.planar = false;
  out.clustered = true;
  for (int m : members)
    for (int p : groups[std::size_t(m)].polygons) {
      const ScenePolygon& poly = scene.polygons()[std::size_t(p)];
      const PlaneFrame frame = planeFrame(poly.vertices, poly.normal);
      Poly2 flat;
      glm::dvec2 lo(1e300), hi(-1e300);
      for (const glm::dvec3& v : poly.vertices) {
        flat.push_back(frame.project(v));
        lo = glm::min(lo, flat.back()), hi = glm::max(hi, flat.back());
      }
      const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
      const double scale = std::min(1.0, kClusterFill * ts / extent);
      for (glm::dvec2& q : flat) q = glm::dvec2(0.5 * ts) + (q - 0.5 * (lo + hi)) * scale;
      out.polygons.push_back(p);
      for (std::size_t k = 1; k + 1 < poly.vertices.size(); ++k) {  // a fan: polygons are convex
        Poly2 uv{flat[0], flat[k], flat[k + 1]};
        if (!(signedArea(uv) > 0)) continue;  // collinear corners
        out.parts.push_back({poly.vertices[0], poly.vertices[k], poly.vertices[k + 1]});
        out.partPolygon.push_back(p);
        out.uv.push_back(std::move(uv));
      }
    }
  return out;
}

int clusterReceiver(const Scene& scene, const std::vector<int>& polygons, const glm::dvec3& centre) {
  int best = polygons.front();
  double nearest = 1e300;
  for (int p : polygons) {
    const ScenePolygon& poly = scene.polygons()[std::size_t(p)];
    const glm::dvec3 d = polygonCentroid(poly.vertices, poly.normal) - centre;
    if (glm::dot(d, d) < nearest) nearest = glm::dot(d, d), best = p;
  }
  return best;
}

std::vector<float> clusterReachBehind(const Scene& scene, const Atlas& atlas) {
  std::vector<float> out(scene.occluderCount(), 0.0f);
  for (std::size_t t = 0; t < atlas.polygonOf.size(); ++t) {
    const std::uint32_t chart = atlas.chartAt(t);
    if (chart == kNoPolygon || !atlas.charts[chart].clustered) continue;
    const ScenePolygon& at = scene.polygons()[atlas.polygonOf[t]];
    double behind = 0;
    for (const Poly3& part : atlas.charts[chart].parts)
      for (const glm::dvec3& v : part) behind = std::max(behind, -at.height(v));
    out[atlas.polygonOf[t]] = float(behind);
  }
  return out;
}

glm::dvec3 polygonCentroid(const Poly3& p, const glm::dvec3& normal) {
  const PlaneFrame frame = planeFrame(p, normal);
  Poly2 flat;
  for (const glm::dvec3& v : p) flat.push_back(frame.project(v));
  return frame.lift(centroid(flat));
}

}  // namespace hemirad
