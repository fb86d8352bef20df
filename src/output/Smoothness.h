// How smooth what is shown is (issue 29's faceting and seam measures, the report's `smoothness`):
// across every edge of one smooth surface (src/output/SmoothEdges.h), at points a texel apart
// along it, the luminance jump between points a sixteenth of a texel either side, each looked up
// on its own polygon as the camera does (Atlas::sample), relative to the luminance there; facet
// edges (both polygons on one chart: a curved chart's facets, a tessellated wall's triangles) and
// seams (two charts) apart. The same measure across as far inside a polygon (its centroid) is the
// baseline: light changes there too, and an edge that jumps no more than that shows no step.
#pragma once
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "src/output/SmoothEdges.h"
#include "src/scene/Atlas.h"

namespace hemirad {

struct Smoothness {
  std::size_t facetEdges = 0, seams = 0;
  // Sum of |luminance jump| over the sum of the mean luminance, over the edges' points of each kind.
  double facetJump = 0, seamJump = 0;
  double insideJump = 0;  // across as far inside the edges' first polygons
};

// `values`: per-texel radiosity as shown (seams stitched, or not, to compare).
Smoothness measureSmoothness(const Scene& scene, const Atlas& atlas, const std::vector<SmoothEdge>& edges,
                             const std::vector<glm::vec4>& values);

}  // namespace hemirad
