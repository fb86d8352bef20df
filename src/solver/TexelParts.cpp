#include "src/solver/TexelParts.h"

#include <algorithm>

namespace hemirad {

namespace {

// The cells (i, j) of chart c that part q (chart coordinates) cuts with more than a sliver, with
// the cut: Atlas's own cut (forEachCut), so the texels listed are the elements.
template <class Fn>
void forEachCut(const Chart& c, const Poly2& q, Fn&& fn) {
  const double ts = c.cellSize;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (glm::dvec2 v : q) lo = glm::min(lo, v), hi = glm::max(hi, v);
  const glm::ivec2 from = glm::clamp(glm::ivec2(glm::floor((lo - c.corner) / ts)) - 1, glm::ivec2(0), c.size);
  const glm::ivec2 to = glm::clamp(glm::ivec2(glm::floor((hi - c.corner) / ts)) + 2, glm::ivec2(0), c.size);
  for (int j = from.y; j < to.y; ++j)
    for (int i = from.x; i < to.x; ++i) {
      Poly2 cut = clipToBox(q, c.corner + glm::dvec2(i, j) * ts, c.corner + glm::dvec2(i + 1, j + 1) * ts);
      if (cut.size() >= 3 && signedArea(cut) > kMinCutFraction * ts * ts) fn(i, j, cut);
    }
}

std::size_t texelOf(const Atlas& atlas, const Chart& c, int i, int j) {
  return std::size_t(c.origin.y + j) * std::size_t(atlas.width) + std::size_t(c.origin.x + i);
}

using Cuts = std::vector<std::pair<std::size_t, glm::uvec2>>;  // texel, (first vertex, count)

// A UV chart's texels as their pieces, already cut (Atlas::blockShape's), each listed as a part
// of its own: the chart's header (zero axes and texel size) makes the shader's prism clip keep
// them whole.
void addUvPieces(const Atlas& atlas, const Chart& c, Cuts& cuts, TexelParts& out) {
  for (std::size_t k = 0; k < c.parts.size(); ++k)
    forEachCut(c, c.uv[k], [&](int i, int j, const Poly2& cut) {
      cuts.emplace_back(texelOf(atlas, c, i, j), glm::uvec2(unsigned(out.charts.size()), unsigned(cut.size())));
      for (glm::dvec2 q : cut) out.charts.push_back(glm::vec4(glm::vec3(liftTriangle(c.parts[k], c.uv[k], q)), 1.0f));
    });
}

}  // namespace

TexelParts texelParts(const Atlas& atlas) {
  TexelParts out;
  for (const Chart& c : atlas.charts) {
    if (c.uvMapped()) {
      out.charts.insert(out.charts.end(), {glm::vec4(0.0f), glm::vec4(0.0f), glm::vec4(0.0f),
                                           glm::vec4(0.0f, 0.0f, float(c.origin.x), float(c.origin.y))});
      continue;
    }
    out.charts.push_back(glm::vec4(glm::vec3(c.frame.origin), 0.0f));
    out.charts.push_back(glm::vec4(glm::vec3(c.frame.u), float(c.cellSize)));
    out.charts.push_back(glm::vec4(glm::vec3(c.frame.v), 0.0f));
    out.charts.push_back(glm::vec4(float(c.corner.x), float(c.corner.y), float(c.origin.x), float(c.origin.y)));
  }
  const std::size_t texels = std::size_t(atlas.width) * std::size_t(atlas.height);
  Cuts cuts;  // in part order
  for (const Chart& c : atlas.charts) {
    if (c.uvMapped()) addUvPieces(atlas, c, cuts, out);
    for (std::size_t k = 0; k < c.parts.size() && !c.uvMapped(); ++k) {
      const Poly3& part = c.parts[k];
      const glm::uvec2 range(unsigned(out.charts.size()), unsigned(part.size()));
      for (auto& v : part) out.charts.push_back(glm::vec4(glm::vec3(v), 1.0f));
      forEachCut(c, c.partInChart(part, k),
                 [&](int i, int j, const Poly2&) { cuts.emplace_back(texelOf(atlas, c, i, j), range); });
    }
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
