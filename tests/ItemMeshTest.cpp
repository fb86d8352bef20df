#include <catch2/catch.hpp>

#include "src/scene/ItemMesh.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("Item mesh level L has 4^L triangles per polygon triangle covering the polygon exactly", "[cpu]") {
  Scene s;
  int m = test::material(s, 0.5, 1.0);
  s.addPolygon(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 2, 1), m, s.addObject("quad"));
  s.addPolygon({{0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, m, s.addObject("tri"));
  for (int level : {0, 1, 3}) {
    std::vector<ItemVertex> mesh = buildItemMesh(s, level);
    REQUIRE(mesh.size() == 3 * itemTriangleCount(s, level));
    CHECK(itemTriangleCount(s, level) == size_t(3) << (2 * level));
    double sum[2] = {0, 0};
    for (size_t i = 0; i < mesh.size(); i += 3) {
      Poly3 t;
      for (int k = 0; k < 3; ++k) t.push_back({mesh[i + k].x, mesh[i + k].y, mesh[i + k].z});
      CHECK(mesh[i].polygon == mesh[i + 1].polygon);
      // Sub-triangles keep their parent's orientation.
      CHECK(glm::dot(newellNormal(t), s.polygons()[mesh[i].polygon].normal) > 0);
      sum[mesh[i].polygon] += area(t);
    }
    CHECK(sum[0] == Approx(2.0));
    CHECK(sum[1] == Approx(0.5));
  }
}
