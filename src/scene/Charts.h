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
// What --chart-angle is unless given: smooth surfaces tessellated at up to ~30 degrees a facet are
// one chart each, so their elements span facets and their light shows no facets (issue 29). H200,
// 100k elements to 90 %: real_20k 403 ms against 1,400 ms at 0, real_80k 2.28 s against 7.18 s
// (docs/bench/h200-2026-12-03b.md); flat scenes (the Cornell box) are bitwise unchanged.
inline constexpr double kDefaultChartAngle = 30;

struct ChartGroup {
  std::vector<int> polygons;  // members in growth order; polygons[0] is the seed
  glm::dvec3 axis{0.0};       // the seed's normal: the projection direction
  bool planar = true;         // every member coplanar with the seed
  // What elements are cut from: a planar chart whose members merge into one convex outline has
  // that outline (the untessellated face: same grid, same cuts); otherwise every member.
  std::vector<Poly3> parts;
  std::vector<int> partPolygon;  // the member each part lies on (the seed for an outline)
  // A UV chart's (ChartMapping.h): per part, a triangle, its vertices' chart coordinates (scene
  // units); a member's parts are consecutive. Empty: the parts are projected along `axis`.
  std::vector<Poly2> uv;
};

// --uv: where charts' texel grids come from. Auto: projection charts (groupCharts); Input: the
// input's lightmap UV islands (src/scene/InputUv.h).
enum class UvSource { Auto, Input };

// Grows charts in polygon order, breadth first; deterministic. angleDegrees: 0 coplanar,
// up to kMaxChartAngle; kPolygonCharts: one chart per polygon.
std::vector<ChartGroup> groupCharts(const Scene& scene, double angleDegrees);
// The charts for --uv `uv`: groupCharts's for Auto.
std::vector<ChartGroup> chartGroups(const Scene& scene, double angleDegrees, UvSource uv);

}  // namespace hemirad
