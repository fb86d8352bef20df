// Where the lightmap's charts go. Up to 1,000 charts: stb_rect_pack's skyline packer over fixed
// candidates (strip widths, two heuristics, charts as they are, all lying or all standing, then
// one chart at a time turned), the least texels kept. Past that, the solve atlas's best-fit
// packer (src/scene/AtlasPacker.h, O(n log n)). The packed region's outer `trim` texels are cut
// away: a chart on the lightmap's border needs no gutter on that side, as CLAMP_TO_EDGE repeats
// its own edge texels there (the sampler the .glb declares). Deterministic: same sizes, same layout.
#pragma once
#include <glm/glm.hpp>
#include <vector>

namespace hemirad {

struct ChartLayout {
  int width = 0, height = 0;        // the image, trimmed
  std::vector<glm::ivec2> corners;  // per rectangle: its lower corner in the image (-trim..: partly cut away)
  std::vector<char> transposed;     // per rectangle: placed with x and y swapped
};

// `sizes` are the charts with their gutters; trimmed sides stay no longer than `maxAspect`
// times the other, and 16384, where any candidate allows.
ChartLayout packCharts(const std::vector<glm::ivec2>& sizes, int trim, double maxAspect);

}  // namespace hemirad
