#include "src/scene/Contacts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace hemirad {

namespace {

struct Edge {
  glm::dvec3 a, b;
  int polygon;
};

// Edges bucketed by the cubic cells their padded boxes cover; an edge over kMaxCells cells is
// "large" and goes to every query instead.
class EdgeGrid {
 public:
  EdgeGrid(const Scene& scene, double pad) : pad_(pad) {
    for (std::size_t p = 0; p < scene.polygons().size(); ++p) {
      const Poly3& v = scene.polygons()[p].vertices;
      for (std::size_t i = 0; i < v.size(); ++i) edges_.push_back({v[i], v[(i + 1) % v.size()], int(p)});
    }
    lo_ = scene.boundsMin() - pad, hi_ = scene.boundsMax() + pad;
    const glm::dvec3 extent = hi_ - lo_;
    const double cells = std::clamp(std::cbrt(double(edges_.size())), 1.0, 1024.0);
    cell_ = std::max({extent.x, extent.y, extent.z}) / cells;
    for (std::size_t e = 0; e < edges_.size(); ++e) {
      const Edge& edge = edges_[e];
      if (!forCells(glm::min(edge.a, edge.b) - pad, glm::max(edge.a, edge.b) + pad, kMaxCells,
                    [&](std::uint64_t key) { grid_[key].push_back(int(e)); }))
        large_.push_back(int(e));
    }
  }
  const std::vector<Edge>& edges() const { return edges_; }
  // The edges whose padded boxes may meet [lo, hi], in edge order.
  std::vector<int> near(glm::dvec3 lo, glm::dvec3 hi) {
    std::vector<int> out = large_;
    ++mark_;
    stamp_.resize(edges_.size(), 0);
    auto take = [&](int e) {
      if (stamp_[std::size_t(e)] != mark_) stamp_[std::size_t(e)] = mark_, out.push_back(e);
    };
    for (int e : large_) stamp_[std::size_t(e)] = mark_;
    const bool bucketed = forCells(lo - pad_, hi + pad_, kMaxQueryCells, [&](std::uint64_t key) {
      if (auto it = grid_.find(key); it != grid_.end())
        for (int e : it->second) take(e);
    });
    if (!bucketed)
      for (std::size_t e = 0; e < edges_.size(); ++e) take(int(e));
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  static constexpr double kMaxCells = 64, kMaxQueryCells = 1 << 20;
  template <class Visit>
  bool forCells(glm::dvec3 lo, glm::dvec3 hi, double limit, Visit visit) const {
    const glm::ivec3 top(int(std::floor((hi_.x - lo_.x) / cell_)), int(std::floor((hi_.y - lo_.y) / cell_)),
                         int(std::floor((hi_.z - lo_.z) / cell_)));
    const glm::ivec3 a = glm::clamp(glm::ivec3(glm::floor((lo - lo_) / cell_)), glm::ivec3(0), top);
    const glm::ivec3 b = glm::clamp(glm::ivec3(glm::floor((hi - lo_) / cell_)), glm::ivec3(0), top);
    if (double(b.x - a.x + 1) * double(b.y - a.y + 1) * double(b.z - a.z + 1) > limit) return false;
    for (int z = a.z; z <= b.z; ++z)
      for (int y = a.y; y <= b.y; ++y)
        for (int x = a.x; x <= b.x; ++x) visit(std::uint64_t(x) << 42 | std::uint64_t(y) << 21 | std::uint64_t(z));
    return true;
  }
  double pad_, cell_ = 1;
  glm::dvec3 lo_{0}, hi_{0};
  std::vector<Edge> edges_;
  std::unordered_map<std::uint64_t, std::vector<int>> grid_;
  std::vector<int> large_;
  std::vector<int> stamp_;
  int mark_ = 0;
};

// Chart c's D0 lines on part k (see the header).
void partContacts(const Atlas& atlas, int c, int k, const std::vector<Edge>& edges, const std::vector<int>& near,
                  double distance, double tolerance, std::vector<ContactLine>& out) {
  const Chart& chart = atlas.charts[std::size_t(c)];
  const PlaneFrame& f = chart.frame;
  Poly2 part;
  for (const glm::dvec3& v : chart.parts[std::size_t(k)]) part.push_back(f.project(v));
  if (signedArea(part) < 0) std::reverse(part.begin(), part.end());
  for (int e : near) {
    const Edge& edge = edges[std::size_t(e)];
    if (atlas.chartOf[std::size_t(edge.polygon)] == std::uint32_t(c)) continue;
    const double sa = glm::dot(edge.a - f.origin, f.n), sb = glm::dot(edge.b - f.origin, f.n);
    if (sa < -tolerance || sb < -tolerance || sa > distance || sb > distance) continue;
    const glm::dvec2 a = f.project(edge.a), b = f.project(edge.b);
    double t0, t1;  // through the interior, clear of the outline
    if (!clipSegment(part, a, b, tolerance, t0, t1) || (t1 - t0) * glm::length(b - a) <= tolerance) continue;
    if (!clipSegment(part, a, b, 0, t0, t1)) continue;
    out.push_back({c, k, a + (b - a) * t0, a + (b - a) * t1, edge.polygon});
  }
}

}  // namespace

double contactDistance(const Scene& scene) {
  return scene.polygons().empty() ? 0 : kContactFraction * glm::length(scene.boundsMax() - scene.boundsMin());
}

std::vector<ContactLine> findContacts(const Scene& scene, const Atlas& atlas, double distance) {
  std::vector<ContactLine> out;
  if (scene.polygons().empty()) return out;
  const double tolerance = kContactTolerance * glm::length(scene.boundsMax() - scene.boundsMin());
  EdgeGrid grid(scene, distance + tolerance);
  for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
    const Chart& chart = atlas.charts[c];
    if (!chart.planar || chart.uvMapped()) continue;
    for (std::size_t k = 0; k < chart.parts.size(); ++k) {
      glm::dvec3 lo(1e300), hi(-1e300);
      for (const glm::dvec3& v : chart.parts[k]) lo = glm::min(lo, v), hi = glm::max(hi, v);
      // Only edges in front: the box grows by `distance` along the normal, not behind.
      const glm::dvec3 front = chart.frame.n * distance;
      const std::vector<int> near = grid.near(glm::min(lo, lo + front), glm::max(hi, hi + front));
      partContacts(atlas, int(c), int(k), grid.edges(), near, distance, tolerance, out);
    }
  }
  return out;
}

}  // namespace hemirad
