// Contact detection for discontinuity meshing (issue 31, "pixel-accurate images"): where another
// polygon touches or nearly touches a receiver (a block standing on the floor, a lamp 0.5 mm under
// the ceiling), the light on the receiver jumps along the touching polygon's outline, the D0
// lines. Those are the other polygons' edges that lie within a small distance in front of (or
// in) the receiver's plane, projected onto it and clipped to its outline; edges along the
// outline itself cut nothing and are dropped.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

// The default contact distance: this fraction of the scene's bounding-box diagonal (Cornell box:
// 0.96 mm, so a lamp 0.5 mm under the ceiling counts and a block 10 cm over the floor does not).
inline constexpr double kContactFraction = 1e-3;
// Lengths and offsets under this fraction of the diagonal are rounding, not geometry.
inline constexpr double kContactTolerance = 1e-7;

double contactDistance(const Scene& scene);  // kContactFraction x the bounding-box diagonal

struct ContactLine {
  int chart = 0;          // the receiving chart of the atlas (planar, projected)
  int part = 0;           // the chart's part it crosses
  glm::dvec2 a{0}, b{0};  // in the chart's plane frame, clipped to the part
  int occluder = 0;       // the scene polygon whose edge it is
};

// Every planar projection chart's D0 lines: other charts' polygon edges with both ends within
// `distance` in front of the chart's plane (or in it) that cross one of its parts' interiors.
// Edges are bucketed in a uniform grid, so each chart meets only the edges near it (near-linear
// in the scene's size). Ordered by chart, part, occluder: deterministic.
std::vector<ContactLine> findContacts(const Scene& scene, const Atlas& atlas, double distance);

}  // namespace hemirad
