// The solution as a lightmap an engine can sample: the atlas's charts repacked tightly with
// stb_rect_pack (src/output/ChartPacker.h; a chart may be placed transposed), each inside a
// gutter of dilated texels (the nearest element's B copied outward), so plain bilinear sampling
// (GL_LINEAR, CLAMP_TO_EDGE) at a polygon's edge reads its own values, never black nor another
// chart. On the lightmap's border the gutter is cut away (when every chart has one): clamping repeats
// the chart's own edge.
// One lightmap texel per element, as in the atlas; rows run from the image's top, as glTF's v does.
// A chart one cell wide (or high) has no gutter across that side: its coordinates there are its
// cells' centre line, so bilinear sampling reads its one column (row) alone, which holds the
// value it has across (on real_400k most charts are such slivers and strips).
#pragma once
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"

namespace hemirad {

struct LightmapOptions {
  // Texels around every chart: bilinear sampling anywhere on a chart reads at most one texel
  // beyond its cells (its grid covers its outline), so one is enough for level 0; not shared
  // between neighbours, whose edge values differ (a shared texel would blend them in).
  int gutter = 1;
  bool dilate = true;    // false: gutters and empty cells stay black (the old atlas; for comparisons)
  double maxAspect = 8;  // the longer side over the shorter, at most (where the charts allow)
};

struct Lightmap {
  int width = 0, height = 0, gutter = 0;
  std::vector<glm::ivec2> origins;  // per polygon: the lightmap texel of its chart's cell (0, 0)
  std::vector<char> transposed;     // per polygon: cell (i, j) at origin + (j, i), not (i, j)
  std::vector<glm::ivec2> gutters;  // per chart, in its own cells' x and y: gutter, or 0 across one cell
  std::vector<glm::vec3> rgb;       // per texel, row-major from row 0
  std::size_t elements = 0;
  std::size_t chartTexels = 0;  // the charts with their gutters, as far as they lie in the image
  // Elements over texels: what of the lightmap holds radiosity. Gutters bound it: a w x h chart
  // fills at most w h / ((w + 2) (h + 2)) of its place, more on the border.
  double texelUse() const { return width && height ? double(elements) / (double(width) * height) : 0; }
  // The packer's part: charts with gutters over texels.
  double packing() const { return width && height ? double(chartTexels) / (double(width) * height) : 0; }
  // Continuous lightmap coordinates (texels) of atlas coordinate `atlasCoord` on polygon `polygon`.
  glm::dvec2 coord(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const;
  // The same as TEXCOORD_1: divided by the size.
  glm::dvec2 uv(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const;
};

// Lays the atlas's charts out anew (deterministically: the same atlas gives the same layout)
// and fills it from the per-atlas-texel radiosity B.
Lightmap buildLightmap(const Atlas& atlas, const std::vector<glm::vec4>& B, const LightmapOptions& options = {});

}  // namespace hemirad
