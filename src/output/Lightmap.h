// The solution as a lightmap an engine can sample: the atlas's charts repacked tightly with
// stb_rect_pack (src/output/ChartPacker.h; a chart may be placed transposed). Plain bilinear
// sampling (GL_LINEAR, CLAMP_TO_EDGE) must read what hemirad's chart-masked lookup does
// (Atlas::sample): within half a texel of a chart's side that lookup reads the side's cells alone.
// By default (gutter 0) the lightmap coordinates are clamped there, to the side cells' centre line,
// and the .glb cuts its triangles along those lines so each piece maps affinely
// (src/output/GltfWriter.cpp): bilinear sampling never leaves the chart's cells, and charts need
// no gutter (issue 29: 1-texel gutters around charts of a few cells capped texel use near 66 %).
// With a gutter (LightmapOptions::gutter >= 1) every chart sits inside that many texels of dilated
// values (the nearest element's B copied outward) instead; on the lightmap's border the gutter is
// cut away (when every chart has one): CLAMP_TO_EDGE repeats the chart's own edge.
// Cells of a chart's rectangle without element are dilated from its elements either way.
// One lightmap texel per element, as in the atlas; rows run from the image's top, as glTF's v does.
// A chart one cell wide (or high) has no gutter across that side: its coordinates there are its
// cells' centre line (the clamp at its narrowest), so bilinear sampling reads its one column alone.
#pragma once
#include <cstddef>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "src/scene/Atlas.h"

namespace hemirad {

struct LightmapOptions {
  // Texels around every chart, 0: none, coordinates clamped to the cells' centres (above). With
  // unclamped coordinates bilinear sampling reads at most one texel beyond a chart's cells (its
  // grid covers its outline), so one is enough for level 0; not shared between neighbours, whose
  // edge values differ (a shared texel would blend them in).
  int gutter = 0;
  bool dilate = true;    // false: gutters and empty cells stay black (the old atlas; for comparisons)
  double maxAspect = 8;  // the longer side over the shorter, at most (where the charts allow)
};

// A point of a polygon with what the .glb interpolates over its triangles (GltfWriter.cpp).
struct SurfacePoint {
  glm::dvec3 position;
  glm::dvec2 atlas, plane;  // atlas and chart coordinates, both affine over a triangle
};
using SurfacePiece = std::vector<SurfacePoint>;  // convex

struct Lightmap {
  int width = 0, height = 0, gutter = 0;
  std::vector<glm::ivec2> origins;  // per polygon: the lightmap texel of its chart's cell (0, 0)
  std::vector<char> transposed;     // per polygon: cell (i, j) at origin + (j, i), not (i, j)
  std::vector<glm::ivec2> gutters;  // per chart, in its own cells' x and y: gutter, or 0 across one cell
                                    // (0: coordinates clamped to the cells' centres on that axis)
  std::vector<glm::vec3> rgb;       // per texel, row-major from row 0
  std::size_t elements = 0;
  std::size_t chartTexels = 0;  // the charts with their gutters, as far as they lie in the image
  // Elements over texels: what of the lightmap holds radiosity. Gutters bound it: a w x h chart
  // fills at most w h / ((w + 2) (h + 2)) of its place, more on the border.
  double texelUse() const { return width && height ? double(elements) / (double(width) * height) : 0; }
  // The packer's part: charts (with their gutters) over texels.
  double packing() const { return width && height ? double(chartTexels) / (double(width) * height) : 0; }
  // Where coord() is the identity (shifted, maybe turned) on polygon `polygon`'s chart: atlas
  // coordinates lo.x <= x <= hi.x, lo.y <= y <= hi.y (infinite: no clamp on that axis); outside, the
  // clamp flattens it. Geometry cut along these lines maps affinely piece by piece.
  void unclamped(const Atlas& atlas, int polygon, glm::dvec2& lo, glm::dvec2& hi) const;
  // Triangle `t` of polygon `polygon` cut along the lines of unclamped(): convex pieces over
  // each of which coord() is affine (the triangle itself where no line crosses it).
  std::vector<SurfacePiece> affinePieces(const Atlas& atlas, int polygon, const SurfacePiece& t) const;
  // Continuous lightmap coordinates (texels) of atlas coordinate `atlasCoord` on polygon `polygon`.
  glm::dvec2 coord(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const;
  // The same as TEXCOORD_1: divided by the size.
  glm::dvec2 uv(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const;
};

// Lays the atlas's charts out anew (deterministically: the same atlas gives the same layout)
// and fills it from the per-atlas-texel radiosity B.
Lightmap buildLightmap(const Atlas& atlas, const std::vector<glm::vec4>& B, const LightmapOptions& options = {});

// " with N-texel gutters" for a layout with gutters, "" without: how the packing share is named.
inline std::string gutterWords(int gutter) {
  return gutter ? " with " + std::to_string(gutter) + "-texel gutters" : "";
}

}  // namespace hemirad
