#include "src/solver/TexelParts.h"

#include <algorithm>

namespace hemirad {

namespace {

// The texels (atlas index) a part cuts with more than a sliver: Atlas's own cut (forEachCut),
// so the texels listed are the elements.
template <class Fn>
void forEachCutTexel(const Atlas& atlas, const Chart& c, const Poly3& part, Fn&& fn) {
  const double ts = c.cellSize;
  Poly2 q;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (auto& v : part) q.push_back(c.frame.project(v)), lo = glm::min(lo, q.back()), hi = glm::max(hi, q.back());
  const glm::ivec2 from = glm::clamp(glm::ivec2(glm::floor((lo - c.corner) / ts)) - 1, glm::ivec2(0), c.size);
  const glm::ivec2 to = glm::clamp(glm::ivec2(glm::floor((hi - c.corner) / ts)) + 2, glm::ivec2(0), c.size);
  for (int j = from.y; j < to.y; ++j)
    for (int i = from.x; i < to.x; ++i) {
      Poly2 cut = clipToBox(q, c.corner + glm::dvec2(i, j) * ts, c.corner + glm::dvec2(i + 1, j + 1) * ts);
      if (cut.size() >= 3 && signedArea(cut) > kMinCutFraction * ts * ts)
        fn(std::size_t(c.origin.y + j) * std::size_t(atlas.width) + std::size_t(c.origin.x + i));
    }
}

}  // namespace

TexelParts texelParts(const Atlas& atlas) {
  TexelParts out;
  for (const Chart& c : atlas.charts) {
    out.charts.push_back(glm::vec4(glm::vec3(c.frame.origin), 0.0f));
    out.charts.push_back(glm::vec4(glm::vec3(c.frame.u), float(c.cellSize)));
    out.charts.push_back(glm::vec4(glm::vec3(c.frame.v), 0.0f));
    out.charts.push_back(glm::vec4(float(c.corner.x), float(c.corner.y), float(c.origin.x), float(c.origin.y)));
  }
  const std::size_t texels = std::size_t(atlas.width) * std::size_t(atlas.height);
  std::vector<std::pair<std::size_t, glm::uvec2>> cuts;  // texel, (first vertex, count); part order
  for (const Chart& c : atlas.charts)
    for (const Poly3& part : c.parts) {
      const glm::uvec2 range(unsigned(out.charts.size()), unsigned(part.size()));
      for (auto& v : part) out.charts.push_back(glm::vec4(glm::vec3(v), 1.0f));
      forEachCutTexel(atlas, c, part, [&](std::size_t t) { cuts.emplace_back(t, range); });
    }
  std::stable_sort(cuts.begin(), cuts.end(), [](auto& a, auto& b) { return a.first < b.first; });
  out.index.assign(texels + 1, 0);
  for (auto& cut : cuts) out.index[cut.first + 1] += 2;
  out.index[0] = unsigned(texels + 1);
  for (std::size_t t = 0; t < texels; ++t) out.index[t + 1] += out.index[t];
  for (auto& cut : cuts) out.index.push_back(cut.second.x), out.index.push_back(cut.second.y);
  return out;
}

}  // namespace hemirad
