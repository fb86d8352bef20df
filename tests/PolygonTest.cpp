#include <catch2/catch.hpp>

#include <random>

#include "src/base/Polygon.h"

using namespace hemirad;

TEST_CASE("Newell normal of a counter-clockwise polygon points to its front with length twice the area", "[cpu]") {
  Poly3 square{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
  glm::dvec3 n = newellNormal(square);
  CHECK(n.z == Approx(8.0));
  CHECK(area(square) == Approx(4.0));
}

TEST_CASE("Clipping a triangle to a box keeps exactly the overlap", "[cpu]") {
  Poly2 tri{{0, 0}, {4, 0}, {0, 4}};
  // The unit box at the origin lies inside: area 1. The box [1,3]^2 holds the triangle's corner
  // x + y <= 4 cut: area 4 - 2 = 2.
  CHECK(signedArea(clipToBox(tri, {0, 0}, {1, 1})) == Approx(1.0));
  CHECK(signedArea(clipToBox(tri, {1, 1}, {3, 3})) == Approx(2.0));
  CHECK(clipToBox(tri, {5, 5}, {6, 6}).empty());
}

TEST_CASE("A box that overlapsBox rejects leaves no area after clipping, and one it keeps leaves some", "[cpu]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int rejected = 0, kept = 0;
  for (int i = 0; i < 2000; ++i) {
    const Poly2 tri{{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const glm::dvec2 lo(u(rng), u(rng)), hi = lo + glm::dvec2(0.05 + 0.5 * (u(rng) + 2), 0.05 + 0.5 * (u(rng) + 2));
    const double cut = std::abs(signedArea(clipToBox(tri, lo, hi)));
    if (!overlapsBox(tri, lo, hi)) {
      ++rejected;
      CHECK(cut == 0.0);
    } else if (cut > 0) {
      ++kept;
    }
  }
  // The random boxes both miss and meet the triangles often, so both branches are exercised.
  CHECK(rejected > 200);
  CHECK(kept > 200);
  // Touching along an edge is no overlap: the clip is degenerate there.
  CHECK_FALSE(overlapsBox({{0, 0}, {1, 0}, {0, 1}}, {1, 0}, {2, 1}));
}

TEST_CASE("Ear clipping triangulates a non-convex polygon with its area and winding", "[cpu]") {
  // An L shape of area 3.
  Poly3 l{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  glm::dvec3 n = newellNormal(l);
  REQUIRE_FALSE(isConvex(l, n));
  std::vector<int> tris = triangulate(l, n);
  REQUIRE(tris.size() == 12);
  double sum = 0;
  for (size_t t = 0; t < tris.size(); t += 3) {
    Poly3 tri{l[tris[t]], l[tris[t + 1]], l[tris[t + 2]]};
    CHECK(glm::dot(newellNormal(tri), n) > 0);
    sum += area(tri);
  }
  CHECK(sum == Approx(3.0));
}

TEST_CASE("Planarity error measures the off-plane vertex", "[cpu]") {
  Poly3 bent{{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}};
  CHECK(planarityError(bent) > 0.02);
  CHECK(planarityError({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) == Approx(0.0).margin(1e-15));
}
