#include "src/output/SeamStitch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "src/output/SmoothEdges.h"

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

// Points every half texel along each seam, each tied to both sides' taps.
std::vector<Constraint> seamConstraints(const Atlas& atlas, const std::vector<SmoothEdge>& edges) {
  std::vector<Constraint> out;
  for (const SmoothEdge& e : edges) {
    if (atlas.chartOf[std::size_t(e.p)] == atlas.chartOf[std::size_t(e.q)]) continue;
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

SeamStitcher::SeamStitcher(const Atlas& atlas, const std::vector<SmoothEdge>& edges)
    : constraints_(seamConstraints(atlas, edges)) {}

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
  return SeamStitcher(atlas, smoothEdges(scene))(std::move(values));
}

}  // namespace hemirad
