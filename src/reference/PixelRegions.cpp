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

// A polygon's image in window coordinates (pixel units, rows bottom-up), clipped to in front of
// the eye; convex for a convex polygon. Solves eye + t (corner + w.x dx + w.y dy) = vertex.
std::vector<glm::dvec2> windowOutline(const ScenePolygon& polygon, const Camera& camera,
                                      const Camera::PixelRays& rays) {
  const glm::dmat3 toRays = glm::inverse(glm::dmat3(rays.corner, rays.dx, rays.dy));
  std::vector<glm::dvec3> in, clipped;  // (t, t w.x, t w.y)
  for (const glm::dvec3& v : polygon.vertices) in.push_back(toRays * (v - camera.eye));
  constexpr double kNear = 1e-9;
  for (std::size_t i = 0; i < in.size(); ++i) {  // Sutherland-Hodgman against t >= kNear
    const glm::dvec3 &a = in[i], &b = in[(i + 1) % in.size()];
    if (a.x >= kNear) clipped.push_back(a);
    if ((a.x >= kNear) != (b.x >= kNear)) clipped.push_back(a + (b - a) * ((kNear - a.x) / (b.x - a.x)));
  }
  std::vector<glm::dvec2> out;
  for (const glm::dvec3& v : clipped) out.emplace_back(v.y / v.x, v.z / v.x);
  return out;
}

// Whether a convex outline and the square [lo, lo + 1]^2 share area (separating axes: the
// square's and the outline's edge normals); touching is not overlapping.
bool overlapsSquare(const std::vector<glm::dvec2>& outline, glm::dvec2 lo) {
  constexpr double kTouch = 1e-6;  // pixels
  if (outline.size() < 3) return false;
  const glm::dvec2 square[4] = {lo, lo + glm::dvec2(1, 0), lo + glm::dvec2(1, 1), lo + glm::dvec2(0, 1)};
  std::vector<glm::dvec2> axes{{1, 0}, {0, 1}};
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const glm::dvec2 e = outline[(i + 1) % outline.size()] - outline[i];
    if (glm::length(e) > 0) axes.push_back(glm::dvec2(-e.y, e.x) / glm::length(e));
  }
  for (const glm::dvec2& n : axes) {
    double a0 = 1e300, a1 = -1e300, b0 = 1e300, b1 = -1e300;
    for (const glm::dvec2& v : outline) a0 = std::min(a0, glm::dot(n, v)), a1 = std::max(a1, glm::dot(n, v));
    for (const glm::dvec2& v : square) b0 = std::min(b0, glm::dot(n, v)), b1 = std::max(b1, glm::dot(n, v));
    if (a1 <= b0 + kTouch || b1 <= a0 + kTouch) return false;
  }
  return true;
}

// Leaves out of the light's band the pixels whose square overlaps the image of an emitter seen
// near them: there a camera's few samples a pixel and the reference's whole-pixel integral
// differ by the light's coverage (a light 150 times the ceiling's B: 1 % of the pixel is +150 %),
// which is anti-aliasing, not the ceiling's radiosity (the edge band's business).
void dropPixelsOverlappingLights(const Scene& scene, const Camera& camera, const std::vector<PixelHit>& hits,
                                 PixelRegions& r) {
  const Camera::PixelRays rays = camera.pixelRays(r.width, r.height);
  std::map<std::uint32_t, std::vector<glm::dvec2>> outlines;
  constexpr int kReach = PixelRegions::kLightReach;
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const std::size_t p = std::size_t(y) * r.width + x;
      if (r.lightDistance[p] > kReach) continue;
      const glm::dvec2 lo(x, r.height - 1 - y);
      for (int dy = -kReach; dy <= kReach && r.lightDistance[p] <= kReach; ++dy)
        for (int dx = -kReach; dx <= kReach; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= r.width || qy >= r.height) continue;
          const std::size_t q = std::size_t(qy) * r.width + qx;
          if (!hits[q].emits) continue;
          auto [it, added] = outlines.try_emplace(r.polygon[q]);
          if (added) it->second = windowOutline(scene.polygons()[r.polygon[q]], camera, rays);
          if (overlapsSquare(it->second, lo)) {
            r.lightDistance[p] = PixelRegions::kFar;
            break;
          }
        }
    }
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
  dropPixelsOverlappingLights(scene, camera, hits, r);
  return r;
}

}  // namespace hemirad
