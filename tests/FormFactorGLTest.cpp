// The GPU pipeline (item buffer + disc form factor + gather) against Howell's closed forms.
// An emitter (rho 0, E 1) shoots each of its elements once; the receiver's area-weighted mean
// B / rho is then its form factor to the emitter, and F_emitter->receiver follows by reciprocity.
#include <catch2/catch.hpp>

#include "cpu/Analytic.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
constexpr double kRho = 0.5;

double gpuFormFactor(const Scene& s, double texelSize, int itemSubdivision) {
  Atlas probe = buildAtlas(s, texelSize);
  unsigned emitterElements = 0;
  for (std::uint32_t p : probe.polygonOf) emitterElements += p != kNoPolygon && s.polygons()[p].object == 0;
  ProgressiveSettings settings;
  settings.shootLevel = 0;  // element by element
  settings.itemSubdivision = itemSubdivision;
  settings.stop.maxShots = emitterElements;  // every emitter element shoots once, nothing else
  test::Solved r = test::solve(s, texelSize, settings);
  REQUIRE(r.status.shots == emitterElements);
  const ObjectRadiosity& receiver = test::object(r, "receiver");
  const ObjectRadiosity& emitter = test::object(r, "emitter");
  return receiver.mean.x / kRho * receiver.area / emitter.area;
}

Scene twoPatches(const Poly3& emitter, const Poly3& receiver) {
  Scene s;
  s.addPolygon(emitter, test::material(s, 0.0, 1.0), s.addObject("emitter"));
  s.addPolygon(receiver, test::material(s, kRho, 0.0), s.addObject("receiver"));
  return s;
}
}  // namespace

TEST_CASE("GPU form factor between parallel opposed rectangles matches Howell C-11 within 0.2%", "[gl]") {
  // a x b rectangles at distance c: (a, b, c) of several aspect ratios.
  for (auto [a, b, c] : {std::tuple{1.0, 1.0, 1.0}, {2.0, 1.0, 1.0}, {1.0, 1.0, 0.5}, {3.0, 1.0, 2.0}}) {
    Scene s = twoPatches(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, a, b),
                         test::rectangle({0, 0, c}, {0, 1, 0}, {1, 0, 0}, b, a));
    double exact = cpu::parallelRectangles(a, b, c);
    double gpu = gpuFormFactor(s, std::min(a, b) / 24, 3);
    INFO("a=" << a << " b=" << b << " c=" << c << " exact " << exact << " gpu " << gpu);
    CHECK(gpu == Approx(exact).epsilon(0.002));
  }
}

TEST_CASE("GPU form factor between perpendicular rectangles sharing an edge matches Howell C-14 within 1.5%", "[gl]") {
  // Emitter on the floor (l along x, w along z), receiver wall (l along x, h along y).
  for (auto [l, w, h] : {std::tuple{1.0, 1.0, 1.0}, {2.0, 1.0, 1.0}, {1.0, 2.0, 0.5}}) {
    Scene s = twoPatches(test::rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, w, l),
                         test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, l, h));
    double exact = cpu::perpendicularRectangles(l, w, h);
    double gpu = gpuFormFactor(s, std::min({l, w, h}) / 24, 3);
    INFO("l=" << l << " w=" << w << " h=" << h << " exact " << exact << " gpu " << gpu);
    CHECK(gpu == Approx(exact).epsilon(0.015));
  }
}

TEST_CASE("Form factors converge to Howell's as elements shrink", "[gl]") {
  Scene s = twoPatches(test::rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 1),
                       test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1));
  double exact = cpu::perpendicularRectangles(1, 1, 1);
  double coarse = std::abs(gpuFormFactor(s, 1.0 / 6, 3) - exact);
  double fine = std::abs(gpuFormFactor(s, 1.0 / 24, 3) - exact);
  INFO("error at 1/6: " << coarse << ", at 1/24: " << fine);
  CHECK(fine < coarse);
}
