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

TEST_CASE("The indexed item mesh draws the same triangles, each shared vertex stored once", "[cpu]") {
  Scene s;
  int m = test::material(s, 0.5, 1.0);
  s.addPolygon(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1), m, s.addObject("a"));
  s.addPolygon(test::rectangle({1, 0, 0}, {0, 0, 1}, {0, 1, 0}, 1, 1), m, s.addObject("b"));  // shares an edge
  const int level = 3;
  const std::vector<ItemVertex> soup = buildItemMesh(s, level);
  const IndexedItemMesh mesh = indexItemMesh(soup);
  REQUIRE(mesh.indices.size() == soup.size());
  for (std::size_t i = 0; i < soup.size(); ++i) {
    const ItemVertex& v = mesh.vertices[mesh.indices[i]];
    CHECK((v.x == soup[i].x && v.y == soup[i].y && v.z == soup[i].z && v.polygon == soup[i].polygon));
  }
  // Each polygon's split grid: (2^L + 1)^2 points; the shared edge's points stay two vertices
  // (one per polygon), as the polygon id is part of the vertex.
  const std::size_t side = (1u << level) + 1;
  CHECK(mesh.vertices.size() == 2 * side * side);
}
