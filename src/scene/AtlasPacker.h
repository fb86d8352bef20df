// Where the solve's atlas puts its charts (issue 29: near-linear, texel use >= 75 %): best-fit
// strip packing (Burke, Kendall and Whitwell, Operations Research 52(4), 2004). The skyline's
// lowest gap (leftmost of the lowest) takes the widest chart that fits it, lying or turned a
// quarter (ties: the taller, then the lower index), against the gap's taller neighbour; a gap no
// chart fits is raised to its lower neighbour. Every step places a chart or removes a skyline
// segment, each in O(log n) through ordered sets: O(n log n) for n charts. No gutters: every
// lookup of the atlas masks by chart (docs/design.md). Deterministic: same sizes, same layout.
#pragma once
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

namespace hemirad {

struct RectLayout {
  int width = 0, height = 0;
  std::vector<glm::ivec2> origins;  // per rectangle: its lower-left cell
  std::vector<char> turned;         // per rectangle: placed as (size.y, size.x)
  std::size_t steps = 0;            // skyline steps taken (tests: near-linear)
};

// Into a strip `width` wide (at least the narrowest side of every rectangle).
RectLayout packBestFit(const std::vector<glm::ivec2>& sizes, int width);
// The best of a few strip widths (from the square's up, and the longest side's): both sides
// within maxSize if any is (the caller checks), then sides within 2 : 1, then the fewest texels.
RectLayout packAtlasCharts(const std::vector<glm::ivec2>& sizes, int maxSize);

}  // namespace hemirad
