// A curved chart's conformal map (issue 29): CGAL's least-squares conformal map (LSCM) of a
// triangulated topological disc onto the plane, scaled so its chart area is its surface area (one
// factor per chart, so --elements and --texel-size mean what they mean for projection charts).
// Refused (no map) unless the input is a connected manifold disc and the map is one-to-one with
// bounded distortion and fills its rectangle: then the caller keeps projection charts
// (src/scene/Charts.h). The map is laid along its minimum-area rectangle. CGAL stays in Lscm.cpp.
#pragma once
#include <array>
#include <vector>

#include "src/base/Polygon.h"

namespace hemirad {

// A map's texels cover a triangle's surface at most this many times denser or sparser than the
// chart's average: max over triangles of max(r, 1/r), r = chart area / surface area. A hemisphere
// (90 degrees of normals about its pole) maps at 2.03 (tests/LscmChartsTest.cpp); more spread
// gets steeply worse (a sphere's conformal map has unbounded area scale).
inline constexpr double kMaxLscmAreaDistortion = 2.5;
// And a triangle's map stretches one direction at most this many times more than the other
// (its Jacobian's singular values' ratio): elements stay near square on the surface.
inline constexpr double kMaxLscmAnisotropy = 3.0;

// A map must fill at least this fraction of its minimum-area rectangle, or its texel grid (laid
// along that rectangle) and its lightmap gutters waste more than projection charts' (real_20k and
// real_400k at 10k and 100k elements: lightmap texel use as with projection or better at 0.75;
// at 0 it fell from 77.6 to 75.1 % and 66.5 to 61.6 % at 100k, docs/real-scenes.md).
inline constexpr double kMinLscmFill = 0.75;

enum class LscmOutcome { Mapped, NotDisc, Degenerate, SolverFailed, Flipped, Distorted, Overlapping, Ragged };

struct LscmMap {
  LscmOutcome outcome = LscmOutcome::NotDisc;
  std::vector<Poly2> uv;      // Mapped: per triangle, its vertices' chart coordinates (scene units)
  double areaDistortion = 0;  // max over triangles of max(r, 1/r) (set once the map is solved)
  double anisotropy = 0;      // max over triangles of the Jacobian's singular values' ratio
};

// The LSCM of `triangles` (indices into `positions`, counter-clockwise seen from the front).
// Deterministic: same input, same map.
LscmMap lscmMap(const std::vector<glm::dvec3>& positions, const std::vector<std::array<int, 3>>& triangles);

}  // namespace hemirad
