// The edges along which one smooth surface continues from polygon to polygon: shared by two
// polygons (vertices welded, src/scene/Welding.h) whose materials reflect and emit alike and
// whose normals lie within kStitchAngle of each other (a sharper crease is a feature), unless the
// edge runs along one of the scene's creases (contact lines, src/scene/ContactCuts.h), where light
// jumps. Across them what is shown should not step: between two charts seam stitching makes it so
// (src/output/SeamStitch.h), within one chart its lookup blends across (src/output/Smoothness.h
// measures both).
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Scene.h"

namespace hemirad {

// A smooth-shading angle, not kMaxChartAngle's 60 degrees as it was: across a furniture model's
// folds (a cushion's top, its rim, its side and its unlit underside) radiosity falls steeply, and
// stitched as one surface the lit charts took the underside's dark (real_20k, 9,916 elements,
// unrefined, to 0.99, against the path-traced reference, couch / armchair bias: -13.2 / -30.5 %
// stitched evenly to 60 degrees, -2.1 / -13.1 % area-weighted to 30, -2.1 / -11.3 % unstitched;
// docs/real-scenes.md).
inline constexpr double kStitchAngle = 30;

struct SmoothEdge {
  int p, q;         // the polygons
  glm::dvec3 a, b;  // the edge's ends, as p has them
};

std::vector<SmoothEdge> smoothEdges(const Scene& scene);

}  // namespace hemirad
