#include "src/reference/PixelRegions.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "src/scene/Atlas.h"
#include "src/scene/Contacts.h"
#include "src/solver/Bvh.h"

namespace hemirad {

namespace {

constexpr std::uint32_t kNoSurface = kNoPolygon;

struct PixelHit {
  std::uint32_t surface = kNoSurface;
  glm::dvec3 point{0.0}, normal{0.0};
  double offset = 0, footprint = 0;  // the plane n . x = offset; the pixel's size on the surface
  bool emits = false;
};

// Per polygon its surface: polygons of one object on one plane (to a millionth of the scene) share one.
std::vector<std::uint32_t> surfaces(const Scene& scene) {
  const double size = std::max(glm::length(scene.boundsMax() - scene.boundsMin()), 1e-30);
  std::map<std::tuple<int, long long, long long, long long, long long>, std::uint32_t> ids;
  std::vector<std::uint32_t> out;
  for (const ScenePolygon& p : scene.polygons()) {
    auto q = [](double v) { return std::llround(v * 1e6); };
    const auto key = std::make_tuple(p.object, q(p.normal.x), q(p.normal.y), q(p.normal.z),
                                     q(glm::dot(p.normal, p.vertices[0]) / size));
    out.push_back(ids.emplace(key, std::uint32_t(ids.size())).first->second);
  }
  return out;
}

std::vector<PixelHit> traceCentres(const Scene& scene, const Camera& camera, int width, int height,
                                   std::vector<std::uint32_t>& polygon) {
  const Bvh bvh(scene);
  const std::vector<std::uint32_t> surface = surfaces(scene);
  const Camera::PixelRays rays = camera.pixelRays(width, height);
  std::vector<PixelHit> hits(std::size_t(width) * height);
  polygon.assign(hits.size(), kNoPolygon);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::dvec3 ray = rays.corner + (x + 0.5) * rays.dx + (height - 1 - y + 0.5) * rays.dy;
      const glm::dvec3 d = glm::normalize(ray);
      const std::optional<BvhHit> hit = bvh.intersect(glm::vec3(camera.eye), glm::vec3(d), kNoPolygon);
      if (!hit) continue;
      const std::size_t p = std::size_t(y) * width + x;
      const ScenePolygon& poly = scene.polygons()[hit->polygon];
      polygon[p] = hit->polygon;
      // A pixel spans |dy| / |ray| radians; on a surface seen at a grazing angle, more.
      const double footprint =
          hit->t * glm::length(rays.dy) / glm::length(ray) / std::max(std::abs(glm::dot(poly.normal, d)), 0.2);
      hits[p] = {surface[hit->polygon],
                 camera.eye + double(hit->t) * d,
                 poly.normal,
                 glm::dot(poly.normal, poly.vertices[0]),
                 footprint,
                 scene.materials[poly.material].emissive()};
    }
  return hits;
}

// Two pixels k apart seeing surfaces that meet at a concave crease: each hit lies on the other's
// plane to within the pixels' reach, and each surface lies in front of the other (n_a - n_b)
// . (x_b - x_a) > 0; an occluding contour fails the first test, a convex edge the second.
bool acrossCrease(const PixelHit& a, const PixelHit& b, int k) {
  if (a.surface == kNoSurface || b.surface == kNoSurface) return false;
  const double reach = 2.0 * (k + 1) * std::max(a.footprint, b.footprint);
  return std::abs(glm::dot(a.normal, b.point) - a.offset) <= reach &&
         std::abs(glm::dot(b.normal, a.point) - b.offset) <= reach &&
         glm::dot(a.normal - b.normal, b.point - a.point) > 0;
}

// A pixel seeing `a` lies beside the light seen at `b`: a's surface is parallel to b's emitter,
// faces its way and lies within `contact` of its plane (flush with it or just above a hung one).
bool besideLight(const PixelHit& a, const PixelHit& b, double contact) {
  return a.surface != kNoSurface && !a.emits && b.emits && glm::dot(a.normal, b.normal) > 1 - 1e-4 &&
         std::abs(a.offset - b.offset) <= contact;
}

}  // namespace

PixelRegions pixelRegions(const Scene& scene, const Camera& camera, int width, int height) {
  PixelRegions r;
  r.width = width, r.height = height;
  const std::vector<PixelHit> hits = traceCentres(scene, camera, width, height, r.polygon);
  r.edgeDistance.assign(hits.size(), PixelRegions::kFar);
  r.creaseDistance.assign(hits.size(), PixelRegions::kFar);
  r.lightDistance.assign(hits.size(), PixelRegions::kFar);
  const double contact = contactDistance(scene);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t p = std::size_t(y) * width + x;
      for (int dy = -PixelRegions::kEdgeReach; dy <= PixelRegions::kEdgeReach; ++dy)
        for (int dx = -PixelRegions::kEdgeReach; dx <= PixelRegions::kEdgeReach; ++dx) {
          const int qx = x + dx, qy = y + dy, k = std::max(std::abs(dx), std::abs(dy));
          if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
          const PixelHit& q = hits[std::size_t(qy) * width + qx];
          if (k <= PixelRegions::kLightReach && besideLight(hits[p], q, contact))
            r.lightDistance[p] = std::min(r.lightDistance[p], k);
          if (q.surface == hits[p].surface) continue;
          r.edgeDistance[p] = std::min(r.edgeDistance[p], k);
          if (k <= PixelRegions::kCreaseReach && acrossCrease(hits[p], q, k))
            r.creaseDistance[p] = std::min(r.creaseDistance[p], k);
        }
    }
  return r;
}

}  // namespace hemirad
