// What stochastic iteration's sampler clips to give a sampled texel its exact shape
// (shaders/texel_shape.glsl): per chart its frame and its parts' vertices, and per atlas texel
// the parts its element is cut from, so a texel of a curved chart spanning several polygons
// shoots as its pieces, like a progressive shooter block (Atlas::blockShape).
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"

namespace hemirad {

struct TexelParts {
  // SSBO_CHARTS: per chart 4 vec4s (plane origin; u axis, w = texel size; v axis; cell (0, 0)'s
  // lower-left corner in plane coordinates (xy) and the chart's atlas origin (zw)), then every
  // chart's parts' vertices (xyz). A UV chart (src/scene/ChartMapping.h) has zero axes and
  // texel size, so the prism clip keeps its parts whole, and its parts are its texels' pieces.
  std::vector<glm::vec4> charts;
  // SSBO_TEXEL_PARTS: entries [index[t], index[t + 1]) for atlas texel t (row-major; width x
  // height + 1 offsets into this same array), each a pair: a part's first vertex in `charts`,
  // its vertex count.
  std::vector<std::uint32_t> index;
};

TexelParts texelParts(const Atlas& atlas);

}  // namespace hemirad
