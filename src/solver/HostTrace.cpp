#include "src/solver/HostTrace.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include <embree3/rtcore.h>

#include "src/scene/Clusters.h"
#include "src/solver/EmbreeScene.h"
#include "src/solver/SolverState.h"

namespace hemirad {

// Named, not anonymous: HostTrace::Impl, of external linkage, holds them.
namespace host_trace {

// A polygon as the GPU's table holds it (src/solver/SolverState.cpp): floats, the plane's offset
// n . v0, and its chart.
struct TracePolygon {
  glm::vec4 plane;
  std::uint32_t chart = kNoPolygon;
  float behind = 0;  // clusterReachBehind
  bool clustered = false;
};

// A cluster shooter's pieces as shaders/formfactor.glsl's clusterEye weighs them.
struct EyePiece {
  glm::vec3 centre, normal;  // vertex mean; Newell's normal, unnormalised (pieceNormal)
  std::uint32_t polygon;
};

struct TraceReceiver {
  glm::vec3 x, b;     // the element's centre, and that onto its polygon's plane
  glm::vec3 n{0.0f};  // its receiver normal
  float reach = 0;    // tracedClear's untested end: half a side on a curved receiver
  std::uint32_t chart = kNoPolygon;
};

}  // namespace host_trace

using host_trace::EyePiece;
using host_trace::TracePolygon;
using host_trace::TraceReceiver;

struct HostTrace::Impl {
  std::unique_ptr<EmbreeScene> scene;
  std::vector<TracePolygon> polygons;
  std::vector<std::uint32_t> trianglePolygon;
  std::vector<TraceReceiver> receivers;
  float eps = 0;
  const Scene* source = nullptr;  // for cluster shooters' pieces
  const Atlas* atlas = nullptr;

  glm::vec3 ontoPlane(glm::vec3 p, std::uint32_t q) const {
    const glm::vec4& plane = polygons[q].plane;
    return p - (glm::dot(glm::vec3(plane), p) - plane.w) * glm::vec3(plane);
  }
  // shaders/segment.glsl's blocksSegment, where Embree found the segment inside one of q's
  // triangles: both ends strictly beyond q's plane. (Its in-polygon test is Embree's watertight
  // one: a segment through the edge two facets share always meets one of them, where the
  // polygons' own edge tests, each rounded on its own plane, may both let it pass.)
  std::vector<EyePiece> clusterParts(const ShooterRecord& s) const;
  glm::vec3 clusterEye(const std::vector<EyePiece>& parts, const TraceReceiver& r, glm::vec3 eye) const;
  bool crosses(std::uint32_t q, glm::vec3 o, glm::vec3 x) const {
    const glm::vec4& plane = polygons[q].plane;
    const float so = glm::dot(glm::vec3(plane), o) - plane.w, sx = glm::dot(glm::vec3(plane), x) - plane.w;
    return (so > eps && sx < -eps) || (so < -eps && sx > eps);
  }
};

namespace {

struct TraceContext {
  RTCIntersectContext base;  // first: Embree hands the filter this pointer
  const HostTrace::Impl* impl;
  glm::vec3 a, end;
  std::uint32_t passA, passB;
};

// Embree hit one of polygon q's triangles: it blocks unless its chart passes or an end lies on its plane.
void occludedFilter(const RTCFilterFunctionNArguments* args) {
  const auto* c = reinterpret_cast<const TraceContext*>(args->context);
  const std::uint32_t q = c->impl->trianglePolygon[RTCHitN_primID(args->hit, args->N, 0)];
  const std::uint32_t chart = c->impl->polygons[q].chart;
  if (chart == c->passA || chart == c->passB || !c->impl->crosses(q, c->a, c->end)) args->valid[0] = 0;
}

void buildScene(HostTrace::Impl& m, const Bvh& bvh) {
  const std::vector<BvhTriangle>& tris = bvh.triangles();
  std::vector<glm::vec3> corners;
  corners.reserve(3 * tris.size());
  m.trianglePolygon.resize(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const glm::vec3 v0(tris[i].v0);
    corners.insert(corners.end(), {v0, v0 + glm::vec3(tris[i].e1), v0 + glm::vec3(tris[i].e2)});
    m.trianglePolygon[i] = floatBitsToUint(tris[i].v0.w);
  }
  // Robust: no nomination lost along shared edges.
  m.scene = std::make_unique<EmbreeScene>(corners, RTC_SCENE_FLAG_ROBUST, occludedFilter);
}

}  // namespace

// The shooter's pieces as the shape table holds them (none if it holds a disc).
std::vector<EyePiece> HostTrace::Impl::clusterParts(const ShooterRecord& s) const {
  std::vector<std::uint32_t> ids;
  const std::vector<Poly3> shape =
      atlas->blockShape(*source, glm::ivec4(s.rect[0], s.rect[1], s.rect[2], s.rect[3]), &ids);
  std::vector<EyePiece> out;
  if (!fitsShapeTable(shape)) return out;
  for (std::size_t k = 0; k < shape.size(); ++k) {
    const Poly3& p = shape[k];
    glm::dvec3 centre(0.0);
    for (const glm::dvec3& v : p) centre += v;
    out.push_back({glm::vec3(centre / double(p.size())), glm::vec3(newellNormal(p)), ids[k]});
  }
  return out;
}

// clusterEye's choice for receiver r, onto its piece's plane as tracedClear puts an eye.
glm::vec3 HostTrace::Impl::clusterEye(const std::vector<EyePiece>& parts, const TraceReceiver& r, glm::vec3 eye) const {
  float best = 0.0f;
  for (const EyePiece& p : parts) {
    const glm::vec3 d = r.x - p.centre;
    const float r2 = glm::dot(d, d),
                w = std::max(glm::dot(p.normal, d), 0.0f) * std::max(-glm::dot(r.n, d), 0.0f) / (r2 * r2);
    if (w > best) best = w, eye = ontoPlane(p.centre, p.polygon);
  }
  return eye;
}

HostTrace::HostTrace(const Scene& scene, const Atlas& atlas, const Bvh& bvh, std::span<const std::uint32_t> receivers,
                     unsigned shooters, float eps)
    : impl_(std::make_unique<Impl>()), words_((shooters + 31) / 32) {
  Impl& m = *impl_;
  m.eps = eps;
  m.source = &scene, m.atlas = &atlas;
  const std::vector<float> behind = clusterReachBehind(scene, atlas);
  for (std::size_t id = 0; id < scene.occluderCount(); ++id) {  // as SolverState uploads them
    const ScenePolygon& p = scene.occluder(id);
    const std::uint32_t chart = id < atlas.chartOf.size() ? atlas.chartOf[id] : kNoPolygon;
    m.polygons.push_back({glm::vec4(glm::vec3(p.normal), float(glm::dot(p.normal, p.vertices[0]))), chart, behind[id],
                          chart != kNoPolygon && atlas.charts[chart].clustered});
  }
  for (std::uint32_t packed : receivers) {
    const std::size_t t = std::size_t(packed >> 16) * std::size_t(atlas.width) + (packed & 0xFFFFu);
    const std::uint32_t q = atlas.polygonOf[t];
    TraceReceiver r;
    r.x = glm::vec3(atlas.positionArea[t]);
    r.n = atlas.normalOf[t];
    r.b = m.ontoPlane(r.x, q);
    const float side = std::sqrt(atlas.positionArea[t].w);
    r.reach = glm::length(r.x - r.b) > 1e-3f * side ? 0.5f * side : 0.0f;
    r.chart = m.polygons[q].chart;
    m.receivers.push_back(r);
  }
  buildScene(m, bvh);
}

HostTrace::~HostTrace() = default;

void HostTrace::trace(std::span<const ShooterRecord> shooters, std::vector<std::uint32_t>& bits) const {
  const Impl& m = *impl_;
  const unsigned words = words_;
  bits.assign(m.receivers.size() * words, 0u);
  struct Eye {
    glm::vec3 o, n, a;
    std::uint32_t chart;
    float behind;                 // the gather's reachBehind
    std::vector<EyePiece> parts;  // a cluster's: seen from the one that sends the receiver the most
  };
  std::vector<Eye> eyes;
  for (const ShooterRecord& s : shooters) {
    const glm::vec3 o(s.positionArea[0], s.positionArea[1], s.positionArea[2]);
    eyes.push_back({o, glm::vec3(s.normal[0], s.normal[1], s.normal[2]), m.ontoPlane(o, s.polygon),
                    m.polygons[s.polygon].chart, m.polygons[s.polygon].behind,
                    m.polygons[s.polygon].clustered ? m.clusterParts(s) : std::vector<EyePiece>{}});
  }
  constexpr std::size_t kChunk = 256;
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    TraceContext c;
    rtcInitIntersectContext(&c.base);
    c.impl = &m;
    for (std::size_t begin; (begin = next.fetch_add(kChunk)) < m.receivers.size();)
      for (std::size_t i = begin; i < std::min(begin + kChunk, m.receivers.size()); ++i) {
        const TraceReceiver& r = m.receivers[i];
        for (std::size_t s = 0; s < eyes.size(); ++s) {
          const Eye& e = eyes[s];
          if (!(glm::dot(r.x - e.o, e.n) > -e.behind)) continue;  // the gather skips it (shooterFormFactor)
          const glm::vec3 a = e.parts.empty() ? e.a : m.clusterEye(e.parts, r, e.a);
          const float keep = std::max(0.0f, 1.0f - r.reach / std::max(glm::length(r.b - a), 1e-30f));
          c.a = a, c.end = a + (r.b - a) * keep, c.passA = r.chart, c.passB = e.chart;
          RTCRay ray{};
          ray.org_x = c.a.x, ray.org_y = c.a.y, ray.org_z = c.a.z;
          ray.dir_x = c.end.x - c.a.x, ray.dir_y = c.end.y - c.a.y, ray.dir_z = c.end.z - c.a.z;
          ray.tnear = 0.0f, ray.tfar = 1.0f, ray.mask = 0xFFFFFFFFu;
          rtcOccluded1(m.scene->get(), &c.base, &ray);
          if (ray.tfar >= 0.0f) bits[i * words + s / 32] |= 1u << (s % 32);  // -inf when blocked
        }
      }
  };
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned k = 1; k < threads; ++k) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace hemirad
