#include <catch2/catch.hpp>

#include "cpu/ExactVisibility.h"

using namespace hemirad;
using V = std::vector<glm::dvec3>;

namespace {
V square(glm::dvec3 o, glm::dvec3 u, glm::dvec3 v) { return {o, o + u, o + u + v, o + v}; }
const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
}  // namespace

TEST_CASE("Exact visibility: an occluder between two points hides them, beside it does not", "[cpu]") {
  // 0: floor, 1: ceiling, 2: a unit blocker half way up covering x in [0, 1], z in [0, 1].
  cpu::ExactVisibility vis(
      {square({-2, 0, -2}, 4.0 * X, 4.0 * Z), square({-2, 2, -2}, 4.0 * Z, 4.0 * X), square({0, 1, 0}, Z, X)});
  CHECK_FALSE(vis.visible({0.5, 0, 0.5}, 0, {0.5, 2, 0.5}, 1));
  CHECK(vis.visible({1.5, 0, 0.5}, 0, {1.5, 2, 0.5}, 1));
  // Grazing: the segment touches the blocker's edge x = 1 exactly: touching counts as hidden...
  CHECK_FALSE(vis.visible({1.0, 0, 0.5}, 0, {1.0, 2, 0.5}, 1));
  // ...and a hair beside it is visible.
  CHECK(vis.visible({1.0 + 1e-9, 0, 0.5}, 0, {1.0 + 1e-9, 2, 0.5}, 1));
}

TEST_CASE("Exact visibility: points on polygons sharing an edge never shadow themselves", "[cpu]") {
  // Floor (0) and wall (1) share the edge z = 0, y = 0; points right at the edge on both.
  cpu::ExactVisibility vis({square({0, 0, 0}, Z, X), square({0, 0, 0}, X, Y)});
  CHECK(vis.visible({0.5, 0, 1e-12}, 0, {0.5, 1e-12, 0}, 1));
  CHECK(vis.visible({0.5, 0, 0}, 0, {0.7, 0.3, 0}, 1));  // a point on the shared edge itself
  CHECK(vis.visible({0.2, 0, 0.9}, 0, {0.8, 0.9, 0}, 1));
}

TEST_CASE("Exact visibility: coplanar neighbours see each other, a coplanar polygon between them hides", "[cpu]") {
  cpu::ExactVisibility vis({square({0, 0, 0}, X, Y), square({1, 0, 0}, X, Y), square({2, 0, 0}, X, Y)});
  CHECK(vis.visible({0.5, 0.5, 0}, 0, {1.5, 0.5, 0}, 1));
  CHECK_FALSE(vis.visible({0.5, 0.5, 0}, 0, {2.5, 0.5, 0}, 2));
  CHECK(vis.triangles() == 6);
}
