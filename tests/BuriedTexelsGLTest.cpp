// Buried texels (src/output/BuriedTexels.h): in a furnace, where every point seen has
// B = E / (1 - rho), floor elements straddling a block's edge see its inside from their centres
// and come out dark; what is shown takes their unburied neighbours' light instead.
#include <catch2/catch.hpp>

#include "src/output/BuriedTexels.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// A unit furnace box (rho 0.5, E 1 on every wall) with a 0.3-wide, 0.3-high block on its floor,
// open at the bottom (as furniture is), off the texel grid.
Scene furnaceWithBlock(glm::dvec2& lo, double& w) {
  Scene s = test::cube(0.5, 1.0);
  const int grey = test::material(s, 0.5, 1.0), block = s.addObject("block");
  lo = {0.37, 0.41}, w = 0.3;
  const double h = 0.3, a = lo.x, b = lo.y;
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  s.addPolygon(test::rectangle({a, h, b}, Z, X, w, w), grey, block);      // top, facing +y
  s.addPolygon(test::rectangle({a, 0, b}, Y, X, h, w), grey, block);      // facing -z
  s.addPolygon(test::rectangle({a, 0, b + w}, X, Y, w, h), grey, block);  // facing +z
  s.addPolygon(test::rectangle({a, 0, b}, Z, Y, w, h), grey, block);      // facing -x
  s.addPolygon(test::rectangle({a + w, 0, b}, Y, Z, h, w), grey, block);  // facing +x
  return s;
}

}  // namespace

TEST_CASE(
    "In a furnace the floor beside a block shows E / (1 - rho): its buried texels take their unburied neighbours' "
    "light, and every other texel keeps its own",
    "[gl][slow]") {
  glm::dvec2 lo;
  double w = 0;
  const Scene s = furnaceWithBlock(lo, w);
  ProgressiveSettings p;
  p.stop.targetConvergence = 0.999;
  const double texel = 1.0 / 12;
  const test::Solved r = test::solve(s, texel, p);
  const BuriedFill fill(s, r.atlas);
  REQUIRE(fill.buried() > 0);
  const std::vector<glm::vec4> shown = fill(r.B);
  // Floor points a quarter texel outside the block's footprint, along its four sides: seen, so 2.
  double solvedError = 0, shownError = 0;
  int points = 0;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 20; ++k) {
      const double t = (k + 0.5) / 20, out = 0.25 * texel;
      const glm::dvec2 q = side == 0   ? glm::dvec2(lo.x - out, lo.y + t * w)
                           : side == 1 ? glm::dvec2(lo.x + w + out, lo.y + t * w)
                           : side == 2 ? glm::dvec2(lo.x + t * w, lo.y - out)
                                       : glm::dvec2(lo.x + t * w, lo.y + w + out);
      const glm::dvec2 c = r.atlas.atlasCoord(0, glm::dvec3(q.x, 0, q.y));  // polygon 0: the floor
      solvedError += std::abs(luminance(glm::dvec3(r.atlas.sample(r.B, 0, c))) - 2) / 2;
      shownError += std::abs(luminance(glm::dvec3(r.atlas.sample(shown, 0, c))) - 2) / 2;
      ++points;
    }
  solvedError /= points, shownError /= points;
  INFO(fill.buried() << " buried texels; floor beside the block, mean |B - 2| / 2: solved " << solvedError << ", shown "
                     << shownError);
  CHECK(shownError < 0.5 * solvedError);
  for (std::size_t t = 0; t < shown.size(); ++t)
    if (fill.backShare()[t] <= kBuriedShare) CHECK(shown[t] == r.B[t]);
}
