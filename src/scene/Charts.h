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

// How a curved chart maps to its texel grid. Lscm: a smooth region (neighbours' normals within
// the chart angle of each other) of up to kLscmSpreads of normal spread is one chart under its
// conformal map (src/scene/Lscm.h) when that map is a one-to-one, little distorted disc, so a sphere
// or cylinder is a few charts, not one per ~30 degrees; elsewhere, and always under Projection,
// charts are projected along their seed's normal. Flat charts are projections under both.
enum class ChartMap { Lscm, Projection };
// An LSCM chart's normals lie within this many degrees of its seed's; a region whose map is
// refused (src/scene/Lscm.h: distorted, or too ragged to fill its texel grid) is grown again
// within the next. A hemisphere maps whole (kMaxLscmAreaDistortion); past 90 degrees a sphere's
// conformal map distorts steeply.
inline constexpr double kLscmSpreads[] = {90, 60, 40, 25};

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
  bool clustered = false;  // small charts sharing one cell (src/scene/Clusters.h)
};

// --uv: where charts' texel grids come from. Auto: charts by --chart-angle, curved ones under LSCM
// (groupCharts, ChartMap::Lscm); Projection: every chart projected (ChartMap::Projection); Input:
// the input's lightmap UV islands (src/scene/InputUv.h).
enum class UvSource { Auto, Input, Projection };

// Grows charts in polygon order, breadth first; deterministic. angleDegrees: 0 coplanar,
// up to kMaxChartAngle; kPolygonCharts: one chart per polygon.
std::vector<ChartGroup> groupCharts(const Scene& scene, double angleDegrees, ChartMap map = ChartMap::Lscm);
// The charts for --uv `uv`: groupCharts's for Auto.
std::vector<ChartGroup> chartGroups(const Scene& scene, double angleDegrees, UvSource uv);

}  // namespace hemirad
