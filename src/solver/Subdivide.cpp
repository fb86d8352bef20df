#include "src/solver/Subdivide.h"

#include <algorithm>
#include <cmath>

#include "gl/State.h"

namespace hemirad {

namespace {

// shaders/gradient.comp's lumIn: float luminance of an element of `chart`, else -1.
float lumIn(const Atlas& atlas, const std::vector<glm::vec4>& B, glm::ivec2 t, std::uint32_t chart) {
  if (t.x < 0 || t.y < 0 || t.x >= atlas.width || t.y >= atlas.height) return -1.0f;
  const std::size_t i = std::size_t(t.y) * std::size_t(atlas.width) + std::size_t(t.x);
  if (atlas.chartAt(i) != chart || !(atlas.positionArea[i].w > 0)) return -1.0f;
  return float(luminance(glm::dvec3(B[i])));
}

}  // namespace

glm::vec2 luminanceSlope(const Atlas& atlas, const std::vector<glm::vec4>& B, glm::ivec2 t, SlopeRule rule) {
  const std::size_t i = std::size_t(t.y) * std::size_t(atlas.width) + std::size_t(t.x);
  const std::uint32_t chart = atlas.chartAt(i);
  const float here = float(luminance(glm::dvec3(B[i])));
  glm::vec2 slope(0.0f);
  for (int axis = 0; axis < 2; ++axis) {
    const glm::ivec2 step = axis == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1);
    const float lo = lumIn(atlas, B, t - step, chart), hi = lumIn(atlas, B, t + step, chart);
    if (lo >= 0 && hi >= 0) {
      const float up = hi - here, down = here - lo;
      if (rule == SlopeRule::Central)
        slope[axis] = 0.5f * (hi - lo);
      else  // minmod
        slope[axis] = float(limitedSlope(up, down));
    } else if (hi >= 0) {
      slope[axis] = hi - here;
    } else if (lo >= 0) {
      slope[axis] = here - lo;
    }
  }
  return slope;
}

float darkestLuminance(const Atlas& atlas, const std::vector<glm::vec4>& B, const SplitRule& rule) {
  double sum = 0, area = 0;
  for (std::size_t t = 0; t < B.size(); ++t)
    if (atlas.polygonOf[t] != kNoPolygon)
      sum += luminance(glm::dvec3(B[t])) * atlas.positionArea[t].w, area += atlas.positionArea[t].w;
  return area > 0 ? float(rule.darkFraction * sum / area) : 0.0f;
}

GradientPass::GradientPass() : program_(computeProgram("gradient.comp")) {}

std::vector<unsigned> GradientPass::count(const SolverState& state, const std::vector<std::int32_t>& leafOf,
                                          std::size_t nodes, float threshold, float darkest) const {
  const gl::Buffer leaves{std::span<const std::int32_t>(leafOf)};
  gl::Buffer counts(std::max<std::size_t>(nodes, 1) * sizeof(unsigned));
  counts.clear(0u);
  gl::barrier(gl::Barrier::Image | gl::Barrier::TextureFetch);
  state.bindScene();
  state.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_ONLY);
  leaves.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_LEAF_OF);
  counts.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_LEAF_COUNTS);
  program_.use();
  program_.set("threshold", threshold);
  program_.set("darkest", darkest);
  gl::Program::dispatch(unsigned(state.atlas.width + 7) / 8, unsigned(state.atlas.height + 7) / 8);
  gl::barrier(gl::Barrier::Storage | gl::Barrier::BufferUpdate);
  std::vector<unsigned> out(nodes, 0);
  if (nodes) counts.read(0, nodes * sizeof(unsigned), out.data());
  return out;
}

std::vector<unsigned> countSteepTexels(const Atlas& atlas, const std::vector<glm::vec4>& B,
                                       const std::vector<std::int32_t>& leafOf, std::size_t nodes, float threshold,
                                       float darkest) {
  std::vector<unsigned> out(nodes, 0);
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      const std::size_t i = std::size_t(y) * std::size_t(atlas.width) + std::size_t(x);
      if (leafOf[i] < 0) continue;
      const float here = float(luminance(glm::dvec3(B[i])));
      if (glm::length(luminanceSlope(atlas, B, {x, y})) > threshold * std::max(here, darkest))
        ++out[std::size_t(leafOf[i])];
    }
  return out;
}

std::size_t splitSteepLeaves(LeafTree& tree, const std::vector<unsigned>& counts, const SplitRule& rule,
                             const ElementBudget& budget) {
  std::vector<std::size_t> steep;  // children added now are not tested this round
  for (std::size_t n = 0; n < tree.nodes().size() && n < counts.size(); ++n)
    if (tree.nodes()[n].leaf() && counts[n] >= rule.count) steep.push_back(n);
  std::stable_sort(steep.begin(), steep.end(), [&](std::size_t a, std::size_t b) { return counts[a] > counts[b]; });
  std::size_t split = 0, elements = budget.elements;
  for (std::size_t n : steep) {
    const std::size_t added = n < budget.leafElements.size() ? 3 * budget.leafElements[n] : 0;
    if (budget.most && elements + added > budget.most) continue;  // a smaller leaf further on may fit
    if (tree.split(int(n))) ++split, elements += added;
  }
  return split;
}

std::vector<std::size_t> leafElements(const std::vector<std::int32_t>& leafOf, std::size_t nodes) {
  std::vector<std::size_t> out(nodes, 0);
  for (std::int32_t leaf : leafOf)
    if (leaf >= 0) ++out[std::size_t(leaf)];
  return out;
}

}  // namespace hemirad
