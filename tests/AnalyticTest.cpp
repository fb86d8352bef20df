#include <catch2/catch.hpp>

#include "cpu/Analytic.h"

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
