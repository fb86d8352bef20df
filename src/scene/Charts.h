// Charts (issue 29): which polygons share one texel grid. A chart is a connected set of
// polygons (sharing edges, welded by position) of one material and one object whose normals lie
// within an angle of its seed's normal; its polygons are projected along that axis onto one
// plane frame, so a tessellated wall is one grid of elements, with no seam at its triangle edges
// and no more elements or shooter blocks than its area needs.
#pragma once
#include <vector>

#include "src/base/Polygon.h"
#include "src/scene/Scene.h"

namespace hemirad {

// "Coplanar" for --chart-angle 0: normals within this many radians.
inline constexpr double kCoplanarRadians = 1e-3;
// The chart angle that keeps every polygon its own chart (benchmarks that compare with
// per-polygon atlases).
inline constexpr double kPolygonCharts = -1;
inline constexpr double kMaxChartAngle = 60;

struct ChartGroup {
  std::vector<int> polygons;  // members in growth order; polygons[0] is the seed
  glm::dvec3 axis{0.0};       // the seed's normal: the projection direction
  bool planar = true;         // every member coplanar with the seed
  // What elements are cut from: a planar chart whose members merge into one convex outline has
  // that outline (the untessellated face: same grid, same cuts); otherwise every member.
  std::vector<Poly3> parts;
  std::vector<int> partPolygon;  // the member each part lies on (the seed for an outline)
};

// Grows charts in polygon order, breadth first; deterministic. angleDegrees: 0 coplanar,
// up to kMaxChartAngle; kPolygonCharts: one chart per polygon.
std::vector<ChartGroup> groupCharts(const Scene& scene, double angleDegrees);

}  // namespace hemirad
