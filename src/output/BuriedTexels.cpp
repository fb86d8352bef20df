#include "src/output/BuriedTexels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "src/solver/EmbreeScene.h"

namespace hemirad {

namespace {

// Embree's scene of every polygon (fans), for back-face queries.
class RayScene {
 public:
  explicit RayScene(const Scene& scene)
      : scene_(corners(scene), RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION) {}  // the filter: nearest(..., frontOnly)

  // Whether a ray from o along d first meets a surface's back: a back face nearer than any front
  // face (a front face as near is its other side: artists model thin parts as two back-to-back
  // faces, whose hits Embree orders arbitrarily). A miss is open space, not a back.
  bool seesBack(glm::vec3 o, glm::vec3 d) const {
    const Hit any = nearest(o, d, false);
    if (any.t < 0 || glm::dot(normal_[any.triangle], d) <= 0) return false;
    const Hit front = nearest(o, d, true);
    return front.t < 0 || front.t > any.t * (1 + 1e-4f) + 1e-6f;
  }

 private:
  struct Hit {
    float t = -1;  // -1: none
    std::uint32_t triangle = 0;
  };
  struct Context {
    RTCIntersectContext base;  // first: Embree hands the filter this pointer
    const RayScene* self;
  };
  Hit nearest(glm::vec3 o, glm::vec3 d, bool frontOnly) const {
    Context context{{}, this};
    rtcInitIntersectContext(&context.base);
    if (frontOnly) context.base.filter = skipBack;
    RTCRayHit rh{};
    rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
    rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
    rh.ray.tfar = 1e30f, rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_.get(), &context.base, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? Hit{} : Hit{rh.ray.tfar, rh.hit.primID};
  }
  static void skipBack(const RTCFilterFunctionNArguments* args) {
    const auto* c = reinterpret_cast<const Context*>(args->context);
    const glm::vec3 d(RTCRayN_dir_x(args->ray, args->N, 0), RTCRayN_dir_y(args->ray, args->N, 0),
                      RTCRayN_dir_z(args->ray, args->N, 0));
    if (glm::dot(c->self->normal_[RTCHitN_primID(args->hit, args->N, 0)], d) > 0) args->valid[0] = 0;
  }

  // Every polygon as a fan, each triangle's normal (its polygon's) kept beside it.
  std::vector<glm::vec3> corners(const Scene& scene) {
    std::vector<glm::vec3> v;
    for (const ScenePolygon& polygon : scene.polygons())
      for (std::size_t i = 1; i + 1 < polygon.vertices.size(); ++i) {
        for (const glm::dvec3& w : {polygon.vertices[0], polygon.vertices[i], polygon.vertices[i + 1]})
          v.emplace_back(w);
        normal_.emplace_back(polygon.normal);
      }
    return v;
  }

  std::vector<glm::vec3> normal_;  // per triangle: its polygon's (filled before scene_ is built)
  EmbreeScene scene_;
};

// The share of texel t's rays that first meet a surface's back.
float backShare(const Scene& scene, const Atlas& atlas, const RayScene& rays, std::size_t t) {
  const ScenePolygon& p = scene.polygons()[atlas.polygonOf[t]];
  const glm::dvec3 n = p.normal, c = glm::dvec3(atlas.positionArea[t]);
  const glm::dvec3 x = c - n * glm::dot(c - p.vertices[0], n) + n * (1e-4 * std::sqrt(atlas.positionArea[t].w));
  const glm::dvec3 u = glm::normalize(glm::cross(std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0), n));
  const glm::dvec3 w = glm::cross(n, u);
  int back = 0;
  for (int k = 0; k < kBuriedRays; ++k) {  // a spiral of equal solid-angle-times-cosine cells
    const double a = (k + 0.5) / kBuriedRays, phi = 2 * M_PI * std::fmod(k * 0.6180339887498949, 1.0);
    const glm::dvec3 d = std::sqrt(a) * (std::cos(phi) * u + std::sin(phi) * w) + std::sqrt(1 - a) * n;
    back += rays.seesBack(glm::vec3(x), glm::vec3(d));
  }
  return float(back) / float(kBuriedRays);
}

std::vector<float> backShares(const Scene& scene, const Atlas& atlas) {
  const RayScene rays(scene);
  std::vector<float> share(atlas.polygonOf.size(), 0.0f);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    constexpr std::size_t kChunk = 256;
    for (std::size_t begin; (begin = next.fetch_add(kChunk)) < share.size();)
      for (std::size_t t = begin; t < std::min(begin + kChunk, share.size()); ++t)
        if (atlas.polygonOf[t] != kNoPolygon) share[t] = backShare(scene, atlas, rays, t);
  };
  std::vector<std::thread> threads(std::max(1u, std::thread::hardware_concurrency()) - 1);
  for (std::thread& th : threads) th = std::thread(work);
  work();
  for (std::thread& th : threads) th.join();
  return share;
}

}  // namespace

BuriedFill::BuriedFill(const Scene& scene, const Atlas& atlas) : share_(backShares(scene, atlas)) {
  auto buried = [&](std::size_t t) { return share_[t] > kBuriedShare; };
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      const std::size_t t = std::size_t(y) * std::size_t(atlas.width) + std::size_t(x);
      if (atlas.polygonOf[t] == kNoPolygon || !buried(t)) continue;
      ++buried_;
      Fill f{t, {}};
      for (int r = 1; r <= kReach && f.from.empty(); ++r)  // the ring r texels out (Chebyshev)
        for (int j = std::max(0, y - r); j <= std::min(atlas.height - 1, y + r); ++j)
          for (int i = std::max(0, x - r); i <= std::min(atlas.width - 1, x + r); ++i) {
            const std::size_t s = std::size_t(j) * std::size_t(atlas.width) + std::size_t(i);
            if (std::max(std::abs(i - x), std::abs(j - y)) == r && atlas.chartAt(s) == atlas.chartAt(t) && !buried(s))
              f.from.push_back(s);
          }
      if (!f.from.empty()) fills_.push_back(std::move(f));
    }
}

std::vector<glm::vec4> BuriedFill::operator()(std::vector<glm::vec4> values) const {
  for (const Fill& f : fills_) {  // reads unburied texels only, which no fill writes
    glm::vec3 sum(0.0f);
    for (std::size_t s : f.from) sum += glm::vec3(values[s]);
    values[f.texel] = glm::vec4(sum / float(f.from.size()), values[f.texel].a);
  }
  return values;
}

}  // namespace hemirad
