// Seam stitching (issue 29): where two charts meet along a shared polygon edge (one surface cut
// into charts by object, by --chart-angle or by a fold), each side's lookup (shaders/camera.frag,
// Atlas::sample) sees only its own chart's texels, so what is shown jumps along the edge. This
// adjusts the texels on both sides so their bilinear samples agree at points along every such
// seam (least squares by Kaczmarz sweeps, as Bakery's and xatlas' seam stitching do). For what
// is shown and exported (camera images, PLY, lightmaps): the solution's elements, the report's
// means and the radiosity hash keep the solved values.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

// Per-texel `values` (atlas order) with every seam stitched. A seam is an edge shared by two
// polygons of different charts whose materials reflect and emit alike and whose normals lie
// within kMaxChartAngle of each other (a sharper crease is a feature, kept), unless it runs
// along one of the scene's creases (contact lines, src/scene/ContactCuts.h).
std::vector<glm::vec4> stitchSeams(const Scene& scene, const Atlas& atlas, std::vector<glm::vec4> values);

}  // namespace hemirad
