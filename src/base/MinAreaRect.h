// The minimum-area bounding rectangle of a point set (issue 29's texel use): a chart's texel grid
// laid along it wastes fewer empty cells than one along an arbitrary in-plane axis (a rotated
// square's axis-aligned box is up to twice its area). Rotating calipers over the convex hull:
// the best rectangle has a side along a hull edge (Freeman and Shapira, 1975).
#pragma once
#include <glm/glm.hpp>
#include <vector>

namespace hemirad {

// Andrew's monotone chain: the hull counter-clockwise, collinear points dropped.
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points);

struct MinAreaRect {
  glm::dvec2 axis{1, 0};  // unit direction of one side (the other is its left normal)
  double area = 0;
};
// Of the hull edges, the first whose rectangle has the least area (in hull order, so the result
// is deterministic); axis (1, 0) and the box's area for fewer than three hull points.
MinAreaRect minAreaRect(const std::vector<glm::dvec2>& points);

}  // namespace hemirad
