#include <catch2/catch.hpp>

#include "cpu/Analytic.h"
#include "cpu/ExactFormFactor.h"

#include <cmath>
#include <tuple>

using namespace hemirad;

TEST_CASE("Howell's closed forms give the tabulated unit-square values", "[cpu]") {
  CHECK(cpu::parallelRectangles(1, 1, 1) == Approx(0.19982).epsilon(1e-4));
  CHECK(cpu::perpendicularRectangles(1, 1, 1) == Approx(0.20004).epsilon(1e-4));
  CHECK(cpu::pointToCoaxialDisc(1, 1) == Approx(0.5));
}

TEST_CASE("Howell's perpendicular rectangles obey reciprocity and the far-plate limit", "[cpu]") {
  for (auto [l, w, h] : {std::tuple{1.0, 2.0, 0.5}, {2.0, 0.3, 1.7}}) {
    CHECK(l * w * cpu::perpendicularRectangles(l, w, h) == Approx(l * h * cpu::perpendicularRectangles(l, h, w)));
  }
  // A very tall wall receives half of what leaves a narrow strip at its foot.
  CHECK(cpu::perpendicularRectangles(1000, 1e-3, 1000) == Approx(0.5).epsilon(1e-3));
  CHECK(cpu::parallelRectangles(1e3, 1e3, 1) == Approx(1.0).epsilon(2e-3));
}

TEST_CASE("Exact point-to-polygon form factor matches the coaxial disc and Nusselt's analogue", "[cpu]") {
  // A 64-gon inscribed in a disc of radius R at height H: area-exact polygon vs the disc formula.
  const double R = 1.0, H = 0.7;
  cpu::Polygon disc;
  for (int k = 63; k >= 0; --k) disc.push_back({R * std::cos(k * 2 * M_PI / 64), R * std::sin(k * 2 * M_PI / 64), H});
  double polygonArea = 0.5 * 64 * R * R * std::sin(2 * M_PI / 64), Req = std::sqrt(polygonArea / M_PI);
  double f = cpu::pointToPolygon({0, 0, 0}, {0, 0, 1}, disc, {0, 0, -1});
  CHECK(f == Approx(cpu::pointToCoaxialDisc(Req, H)).epsilon(2e-3));
  // From behind the polygon's front side nothing is received.
  CHECK(cpu::pointToPolygon({0, 0, 2}, {0, 0, -1}, disc, {0, 0, -1}) == 0.0);
  // A huge square far across the tangent plane: the horizon clip leaves half the hemisphere.
  cpu::Polygon wall{{0, -1e4, -1e4}, {0, -1e4, 1e4}, {0, 1e4, 1e4}, {0, 1e4, -1e4}};
  CHECK(cpu::pointToPolygon({-1e-3, 0, 0}, {0, 0, 1}, wall, {-1, 0, 0}) == Approx(0.5).epsilon(1e-6));
}

TEST_CASE("Exact form factors integrate to Howell's closed forms to 1e-6", "[cpu]") {
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  for (auto [a, b, c] : {std::tuple{1.0, 1.0, 1.0}, {2.0, 1.0, 0.5}, {1.0, 3.0, 2.0}}) {
    // From the a x b rectangle at z = 0 (front +z) to the one at z = c (front -z).
    cpu::Polygon top{{0, 0, c}, {0, b, c}, {a, b, c}, {a, 0, c}};
    CHECK(cpu::rectangleToPolygon({0, 0, 0}, X, Y, a, b, top, -Z) ==
          Approx(cpu::parallelRectangles(a, b, c)).margin(1e-6));
  }
  for (auto [l, w, h] : {std::tuple{1.0, 1.0, 1.0}, {2.0, 1.0, 0.5}, {1.0, 0.4, 3.0}}) {
    // From the floor (x along l, z along w; front -x cross z = +y) to the wall at z = 0 (front +z),
    // the quadrature graded toward their shared edge at z = 0.
    cpu::Polygon wall{{0, 0, 0}, {l, 0, 0}, {l, h, 0}, {0, h, 0}};
    CHECK(cpu::rectangleToPolygon({l, 0, 0}, -X, Z, l, w, wall, Z) ==
          Approx(cpu::perpendicularRectangles(l, w, h)).margin(1e-6));
  }
}
