// The bench's scene-size columns (src/bench/SceneSize.h): triangles count each convex n-gon as
// n - 2, and texel use is the elements' share of the atlas's texels; the triangle ceiling splits
// a large scene's item mesh less (src/bench/Ceilings.h).
#include <catch2/catch.hpp>
#include <cmath>

#include "src/bench/Ceilings.h"
#include "src/bench/SceneSize.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("Bench scene size counts a triangle a quad and a pentagon as 6 triangles in 3 polygons", "[cpu]") {
  Scene s;
  int m = test::material(s, 0.5, 1.0);
  int o = s.addObject("shapes");
  s.addPolygon({{0, 0, 0}, {1, 0, 0}, {0.3, 0.8, 0}}, m, o);
  s.addPolygon(test::rectangle({0, 0, 1}, {1, 0, 0}, {0, 1, 0}, 1.0, 1.0), m, o);
  Poly3 pentagon;
  for (int k = 4; k >= 0; --k) pentagon.push_back({2 + std::cos(k * 2 * M_PI / 5), 0.5, std::sin(k * 2 * M_PI / 5)});
  s.addPolygon(pentagon, m, o);
  SceneSize size = sceneSize(s);
  CHECK(size.polygons == 3);
  CHECK(size.triangles == 1 + 2 + 3);
}

TEST_CASE("Bench texel use of a unit square at texel 1/4 is its 16 elements over the atlas", "[cpu]") {
  Scene s;
  s.addPolygon(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1.0, 1.0), test::material(s, 0.5, 1.0),
               s.addObject("square"));
  Atlas a = buildAtlas(s, 0.25);
  REQUIRE(a.elements == 16);
  CHECK(a.width * a.height == 16);  // no gutters (src/scene/AtlasPacker.h): the chart is the atlas
  CHECK(texelUse(a) == Approx(16.0 / (a.width * a.height)));
  CHECK(texelUse(Atlas{}) == 0.0);
}

TEST_CASE("Bench triangle ceiling keeps L6 for the Cornell box and splits real scenes under 2^22 triangles", "[cpu]") {
  CHECK(ceilingLevel(32) == 6);       // 131,072 item triangles
  CHECK(ceilingLevel(21004) == 3);    // 1,344,256; L4 would be 5,376,024
  CHECK(ceilingLevel(1029046) == 1);  // 4,116,184
  CHECK(ceilingLevel(5000000) == 0);  // drawn unsplit however large
}
