#include "src/solver/Bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>

#include "src/base/Error.h"

namespace hemirad {

std::uint32_t floatBitsToUint(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

float uintBitsToFloat(std::uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

namespace {

// Möller-Trumbore, as shaders/bvh.glsl: t of the hit, or a negative number. Both sides hit.
float hitTriangle(const BvhTriangle& tri, glm::vec3 o, glm::vec3 d) {
  const glm::vec3 e1(tri.e1), e2(tri.e2), p = glm::cross(d, e2);
  const float det = glm::dot(e1, p);
  if (det == 0.0f) return -1.0f;
  const float inv = 1.0f / det;
  const glm::vec3 s = o - glm::vec3(tri.v0);
  const float u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return -1.0f;
  const glm::vec3 q = glm::cross(s, e1);
  const float v = glm::dot(d, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return -1.0f;
  return glm::dot(e2, q) * inv;
}

// Slab test: the entry distance, or +inf when the ray misses the box before tMax.
float hitBox(const BvhNode& n, glm::vec3 o, glm::vec3 invD, float tMax) {
  const glm::vec3 t0 = (glm::vec3(n.lo) - o) * invD, t1 = (glm::vec3(n.hi) - o) * invD;
  const glm::vec3 lo = glm::min(t0, t1), hi = glm::max(t0, t1);
  const float enter = std::max(std::max(lo.x, lo.y), std::max(lo.z, 0.0f));
  const float leave = std::min(std::min(hi.x, hi.y), std::min(hi.z, tMax));
  return enter <= leave ? enter : std::numeric_limits<float>::infinity();
}

}  // namespace

Bvh::Bvh(const Scene& scene) {
  std::vector<BvhTriangle>& tris = triangles_;  // input order until the build reorders them
  for (std::uint32_t id = 0; id < scene.polygons().size(); ++id) {
    const Poly3& v = scene.polygons()[id].vertices;
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const glm::vec3 a(v[0]), b(v[k]), c(v[k + 1]);
      tris.push_back({glm::vec4(a, uintBitsToFloat(id)), glm::vec4(b - a, 0.0f), glm::vec4(c - a, 0.0f)});
      centroids_.push_back((a + b + c) / 3.0f);
    }
  }
  if (tris.empty()) throw InputError("the scene has no triangles to trace");
  std::vector<std::uint32_t> order(tris.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  nodes_.reserve(2 * tris.size());
  build(order, 0, order.size(), 1);
  std::vector<BvhTriangle> sorted;
  sorted.reserve(tris.size());
  for (std::uint32_t i : order) sorted.push_back(tris[i]);
  triangles_ = std::move(sorted);
  centroids_.clear();
  if (depth_ > kMaxDepth) fail("the scene's BVH is {} levels deep, more than the build allows ({})", depth_, kMaxDepth);
}

namespace {

constexpr int kBins = 16;

float halfArea(glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 e = glm::max(hi - lo, glm::vec3(0.0f));
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

}  // namespace

// The binned surface-area heuristic (Wald 2007) over order[begin, end): kBins bins of the
// centroids' bounds on each axis, the boundary that minimises A_left N_left + A_right N_right.
// Returns the first index of the right part after partitioning, or `begin` when no boundary
// separates the centroids. A room's walls span it whole: where a median split buries them in
// leaves whose every ancestor is then as large as the room, the heuristic cuts them off near the
// root, so a segment through a furnished corner visits few boxes.
std::size_t Bvh::splitBySah(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, glm::vec3 clo,
                            glm::vec3 chi) {
  struct Bin {
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    std::size_t count = 0;
  };
  float best = std::numeric_limits<float>::max();
  int bestAxis = -1, bestBin = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const float extent = chi[axis] - clo[axis];
    if (!(extent > 0.0f)) continue;
    std::array<Bin, kBins> bins;
    for (std::size_t i = begin; i < end; ++i) {
      const BvhTriangle& t = triangles_[order[i]];
      const glm::vec3 a(t.v0), b = a + glm::vec3(t.e1), c = a + glm::vec3(t.e2);
      Bin& bin = bins[binOf(centroids_[order[i]][axis], clo[axis], extent)];
      bin.lo = glm::min(bin.lo, glm::min(a, glm::min(b, c))), bin.hi = glm::max(bin.hi, glm::max(a, glm::max(b, c)));
      ++bin.count;
    }
    std::array<float, kBins> rightCost{};  // rightCost[k]: bins k.. as one child
    Bin right;
    for (int k = kBins - 1; k > 0; --k) {
      right.lo = glm::min(right.lo, bins[k].lo), right.hi = glm::max(right.hi, bins[k].hi),
      right.count += bins[k].count;
      rightCost[k] = right.count ? halfArea(right.lo, right.hi) * float(right.count) : 0.0f;
    }
    Bin left;
    for (int k = 1; k < kBins; ++k) {  // boundary before bin k
      left.lo = glm::min(left.lo, bins[k - 1].lo), left.hi = glm::max(left.hi, bins[k - 1].hi);
      left.count += bins[k - 1].count;
      if (left.count == 0 || left.count == end - begin) continue;
      const float cost = halfArea(left.lo, left.hi) * float(left.count) + rightCost[k];
      if (cost < best) best = cost, bestAxis = axis, bestBin = k;
    }
  }
  if (bestAxis < 0) return begin;
  const float lo = clo[bestAxis], extent = chi[bestAxis] - clo[bestAxis];
  const auto mid = std::stable_partition(order.begin() + long(begin), order.begin() + long(end), [&](std::uint32_t i) {
    return binOf(centroids_[i][bestAxis], lo, extent) < bestBin;
  });
  return std::size_t(mid - order.begin());
}

int Bvh::binOf(float c, float lo, float extent) { return std::min(kBins - 1, int(float(kBins) * (c - lo) / extent)); }

// Node of order[begin, end); returns its index. Children are split by the surface-area heuristic
// (splitBySah), or at the median centroid along the longest axis of the centroids' bounds where the
// heuristic finds no split or the levels left (kMaxDepth) could not hold a median split's.
int Bvh::build(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end, int depth) {
  depth_ = std::max(depth_, depth);
  const int index = int(nodes_.size());
  nodes_.push_back({});
  glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  glm::vec3 clo = lo, chi = hi;
  for (std::size_t i = begin; i < end; ++i) {  // order[i] indexes the input (unsorted) triangles
    const BvhTriangle& t = triangles_[order[i]];
    const glm::vec3 a(t.v0), b = a + glm::vec3(t.e1), c = a + glm::vec3(t.e2);
    lo = glm::min(glm::min(lo, a), glm::min(b, c));
    hi = glm::max(glm::max(hi, a), glm::max(b, c));
    clo = glm::min(clo, centroids_[order[i]]);
    chi = glm::max(chi, centroids_[order[i]]);
  }
  nodes_[index] = {glm::vec4(lo, uintBitsToFloat(std::uint32_t(begin))), glm::vec4(hi, uintBitsToFloat(0u))};
  if (end - begin <= std::size_t(kLeafSize)) {
    nodes_[index].hi.w = uintBitsToFloat(std::uint32_t(end - begin));
    return index;
  }
  const double medianLevels = std::ceil(std::log2(double(end - begin) / kLeafSize));
  std::size_t mid = depth + int(medianLevels) + 1 < kMaxDepth ? splitBySah(order, begin, end, clo, chi) : begin;
  if (mid > begin) {
    build(order, begin, mid, depth + 1);
    build(order, mid, end, depth + 1);
    nodes_[index].lo.w = uintBitsToFloat(std::uint32_t(nodes_.size()));
    return index;
  }
  const glm::vec3 extent = chi - clo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  mid = begin + (end - begin) / 2;
  std::nth_element(order.begin() + long(begin), order.begin() + long(mid), order.begin() + long(end),
                   [&](std::uint32_t a, std::uint32_t b) {
                     return centroids_[a][axis] < centroids_[b][axis] ||
                            (centroids_[a][axis] == centroids_[b][axis] && a < b);
                   });
  build(order, begin, mid, depth + 1);
  build(order, mid, end, depth + 1);
  nodes_[index].lo.w = uintBitsToFloat(std::uint32_t(nodes_.size()));
  return index;
}

// As bvh.glsl's bvhNext: into an inner node whose box the walk meets, else past it.
std::uint32_t Bvh::next(std::uint32_t n, bool enter) const {
  const bool leaf = floatBitsToUint(nodes_[n].hi.w) != 0;
  return enter || leaf ? n + 1 : floatBitsToUint(nodes_[n].lo.w);
}

std::optional<BvhHit> Bvh::intersect(glm::vec3 origin, glm::vec3 dir, std::uint32_t skip) const {
  const glm::vec3 invD = 1.0f / dir;
  std::optional<BvhHit> best;
  float tMax = std::numeric_limits<float>::max();
  for (std::uint32_t k = 0, end = next(0, false); k < end;) {
    const BvhNode& n = nodes_[k];
    const bool hit = hitBox(n, origin, invD, tMax) != std::numeric_limits<float>::infinity();
    const std::uint32_t first = floatBitsToUint(n.lo.w), count = floatBitsToUint(n.hi.w);
    for (std::uint32_t i = first; hit && i < first + count; ++i) {  // a leaf's triangles
      if (floatBitsToUint(triangles_[i].v0.w) == skip) continue;
      const float t = hitTriangle(triangles_[i], origin, dir);
      if (t > 0.0f && t < tMax) tMax = t, best = BvhHit{t, floatBitsToUint(triangles_[i].v0.w), i};
    }
    k = next(k, hit);
  }
  return best;
}

std::optional<BvhHit> Bvh::intersectAll(glm::vec3 origin, glm::vec3 dir, std::uint32_t skip) const {
  std::optional<BvhHit> best;
  for (std::uint32_t i = 0; i < triangles_.size(); ++i) {
    if (floatBitsToUint(triangles_[i].v0.w) == skip) continue;
    const float t = hitTriangle(triangles_[i], origin, dir);
    if (t > 0.0f && (!best || t < best->t)) best = BvhHit{t, floatBitsToUint(triangles_[i].v0.w), i};
  }
  return best;
}

}  // namespace hemirad
