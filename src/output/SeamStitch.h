// Seam stitching (issue 29): where two charts meet along a shared polygon edge (one surface cut
// into charts by object, by --chart-angle or by a fold), each side's lookup (shaders/camera.frag,
// Atlas::sample) sees only its own chart's texels, so what is shown jumps along the edge. This
// adjusts the texels on both sides so their bilinear samples agree at points along every such
// seam (least squares by Kaczmarz sweeps, as Bakery's and xatlas' seam stitching do). For what
// is shown and exported (camera images, PLY, lightmaps): the solution's elements, the report's
// means and the radiosity hash keep the solved values.
#pragma once
#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "src/output/SmoothEdges.h"
#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

// A seam is an edge of one smooth surface (src/output/SmoothEdges.h) between two charts. The
// seams' sample points are found once per layout, so live views (the viewer, walkthroughs,
// animations: Renderer::stitchLive) stitch every frame at the cost of the sweeps.
class SeamStitcher {
 public:
  // `edges`: smoothEdges(scene), which its caller may need too (the report's smoothness).
  SeamStitcher(const Atlas& atlas, const std::vector<SmoothEdge>& edges);
  // Per-texel `values` (atlas order) with every seam stitched.
  std::vector<glm::vec4> operator()(std::vector<glm::vec4> values) const;
  bool empty() const { return constraints_.empty(); }

  // A sample point's taps on one chart: the bilinear texels of that chart, weights normalised
  // over them (Atlas::sample's blend), and each texel's share of a change, its weight over its
  // area: a seam is closed by the change of least area-weighted square, so a chart's sliver
  // texels bend to a large texel beside them rather than drag it (a cushion's top, two texels,
  // joins through its rim's slivers the unlit underside; stitched evenly, the top took its dark).
  struct Taps {
    std::array<std::size_t, 4> texel{};
    std::array<double, 4> weight{}, give{};
    int count = 0;
    double norm2 = 0;  // sum of weight x give
  };
  struct Constraint {  // one sample point of a seam, as each side looks it up
    Taps a, b;
  };

 private:
  std::vector<Constraint> constraints_;
};

// SeamStitcher(atlas, smoothEdges(scene))(values), for one use.
std::vector<glm::vec4> stitchSeams(const Scene& scene, const Atlas& atlas, std::vector<glm::vec4> values);

}  // namespace hemirad
