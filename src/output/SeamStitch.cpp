#include "src/output/SeamStitch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "src/scene/Contacts.h"
#include "src/scene/Welding.h"

namespace hemirad {

namespace {

// Sweeps over the seam constraints: each makes its two samples agree exactly; sweeps settle
// the texels several constraints share (a texel's 2 x 2 neighbourhood holds a few).
constexpr int kSweeps = 32;
// A texel's area in the weighted change (below): a floor, for texels of zero area by rounding.
constexpr double kMinArea = 1e-30;

using Taps = SeamStitcher::Taps;
using Constraint = SeamStitcher::Constraint;

Taps tapsAt(const Atlas& atlas, int polygon, glm::dvec3 p) {
  const std::uint32_t chart = atlas.chartOf[std::size_t(polygon)];
  const glm::dvec2 c = atlas.atlasCoord(polygon, p) - 0.5;
  const glm::ivec2 i0(glm::floor(c));
  const glm::dvec2 f = c - glm::dvec2(i0);
  Taps t;
  double sum = 0;
  for (int k = 0; k < 4; ++k) {
    const glm::ivec2 o(k & 1, k >> 1), at = i0 + o;
    const double w = (o.x ? f.x : 1 - f.x) * (o.y ? f.y : 1 - f.y);
    if (at.x < 0 || at.y < 0 || at.x >= atlas.width || at.y >= atlas.height || w <= 0) continue;
    const std::size_t index = std::size_t(at.y) * std::size_t(atlas.width) + std::size_t(at.x);
    if (atlas.chartAt(index) != chart) continue;
    t.texel[std::size_t(t.count)] = index, t.weight[std::size_t(t.count)] = w, ++t.count, sum += w;
  }
  for (int k = 0; k < t.count; ++k) {
    const std::size_t i = std::size_t(k);
    t.weight[i] /= sum;
    t.give[i] = t.weight[i] / std::max(double(atlas.positionArea[t.texel[i]].w), kMinArea);
    t.norm2 += t.weight[i] * t.give[i];
  }
  return t;
}

bool alike(const Scene& scene, const ScenePolygon& p, const ScenePolygon& q) {
  const Material &m = scene.materials[p.material], &n = scene.materials[q.material];
  return m.reflectance == n.reflectance && m.emission == n.emission &&
         glm::dot(p.normal, q.normal) >= std::cos(kStitchAngle * M_PI / 180);
}

// Polygon pairs sharing an edge (vertices welded, src/scene/Welding.h), with the edge as the first has it.
struct SharedEdge {
  int p, q;
  glm::dvec3 a, b;
};
std::vector<SharedEdge> sharedEdges(const Scene& scene) {
  const Welding w = weldVertices(scene);
  std::vector<SharedEdge> out;
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

// Points every half texel along each seam, each tied to both sides' taps.
std::vector<Constraint> seamConstraints(const Scene& scene, const Atlas& atlas) {
  std::vector<Constraint> out;
  const Creases creases(scene);
  for (const SharedEdge& e : sharedEdges(scene)) {
    if (atlas.chartOf[std::size_t(e.p)] == atlas.chartOf[std::size_t(e.q)]) continue;
    if (!alike(scene, scene.polygons()[std::size_t(e.p)], scene.polygons()[std::size_t(e.q)])) continue;
    if (creases.along(e.a, e.b)) continue;
    const double cell = std::min(atlas.charts[atlas.chartOf[std::size_t(e.p)]].cellSize,
                                 atlas.charts[atlas.chartOf[std::size_t(e.q)]].cellSize);
    const int n = std::max(2, int(std::ceil(2 * glm::length(e.b - e.a) / cell)));
    for (int k = 0; k < n; ++k) {
      const glm::dvec3 x = e.a + (e.b - e.a) * ((k + 0.5) / n);
      Constraint c{tapsAt(atlas, e.p, x), tapsAt(atlas, e.q, x)};
      if (c.a.count > 0 && c.b.count > 0) out.push_back(c);
    }
  }
  return out;
}

glm::dvec3 sampleOf(const Taps& t, const std::vector<glm::vec4>& values) {
  glm::dvec3 s(0.0);
  for (int k = 0; k < t.count; ++k) s += t.weight[std::size_t(k)] * glm::dvec3(values[t.texel[std::size_t(k)]]);
  return s;
}

// Moves t's texels by lambda times their shares (Taps::give).
void shift(const Taps& t, glm::dvec3 lambda, std::vector<glm::vec4>& values) {
  for (int k = 0; k < t.count; ++k) {
    glm::vec4& v = values[t.texel[std::size_t(k)]];
    v = glm::vec4(glm::max(glm::vec3(glm::dvec3(v) + lambda * t.give[std::size_t(k)]), glm::vec3(0.0f)), v.a);
  }
}

}  // namespace

SeamStitcher::SeamStitcher(const Scene& scene, const Atlas& atlas) : constraints_(seamConstraints(scene, atlas)) {}

std::vector<glm::vec4> SeamStitcher::operator()(std::vector<glm::vec4> values) const {
  for (int sweep = 0; sweep < kSweeps && !constraints_.empty(); ++sweep)
    for (const Constraint& c : constraints_) {
      // The change of least area-weighted square (sum of area x change^2) that closes the gap.
      const glm::dvec3 lambda = (sampleOf(c.b, values) - sampleOf(c.a, values)) / (c.a.norm2 + c.b.norm2);
      shift(c.a, lambda, values), shift(c.b, -lambda, values);
    }
  return values;
}

std::vector<glm::vec4> stitchSeams(const Scene& scene, const Atlas& atlas, std::vector<glm::vec4> values) {
  return SeamStitcher(scene, atlas)(std::move(values));
}

}  // namespace hemirad
