#include <catch2/catch.hpp>
#include <cmath>

#include "src/scene/Atlas.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
Scene shapes() {
  Scene s;
  int m = test::material(s, 0.5, 1.0);
  int o = s.addObject("shapes");
  s.addPolygon({{0, 0, 0}, {1, 0, 0}, {0.3, 0.8, 0}}, m, o);                        // triangle
  s.addPolygon(test::rectangle({0, 0, 1}, {1, 0, 0}, {0, 0.6, 0.8}, 1.3, 0.7), m, o);  // tilted quad
  Poly3 pentagon;
  for (int k = 0; k < 5; ++k) pentagon.push_back({2 + std::cos(k * 2 * M_PI / 5), 0.5, std::sin(k * 2 * M_PI / 5)});
  std::reverse(pentagon.begin(), pentagon.end());
  s.addPolygon(pentagon, m, o);
  return s;
}
}  // namespace

TEST_CASE("Atlas element areas sum to each polygon's area, partial texels included", "[cpu]") {
  Scene s = shapes();
  for (double ts : {0.5, 0.11, 0.037}) {
    Atlas a = buildAtlas(s, ts);
    std::vector<double> sum(s.polygons().size(), 0.0);
    for (size_t t = 0; t < a.polygonOf.size(); ++t)
      if (a.polygonOf[t] != kNoPolygon) sum[a.polygonOf[t]] += a.positionArea[t].w;
    for (size_t p = 0; p < sum.size(); ++p) CHECK(sum[p] == Approx(s.polygons()[p].area).epsilon(1e-6));
  }
}

TEST_CASE("Atlas element centres lie on their polygon and match their cut's centroid", "[cpu]") {
  Scene s = shapes();
  Atlas a = buildAtlas(s, 0.09);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      size_t t = size_t(y) * a.width + x;
      if (a.polygonOf[t] == kNoPolygon) continue;
      const ScenePolygon& p = s.polygons()[a.polygonOf[t]];
      glm::dvec3 c(a.positionArea[t]);
      CHECK(std::abs(glm::dot(c - p.vertices[0], p.normal)) < 1e-5);
      Poly3 cut = a.elementShape(s, x, y);
      CHECK(area(cut) == Approx(a.positionArea[t].w).epsilon(1e-5));
      // The cut is convex, so its centroid is inside it: inside every edge's half-plane.
      for (size_t k = 0; k < cut.size(); ++k)
        CHECK(glm::dot(glm::cross(cut[(k + 1) % cut.size()] - cut[k], c - cut[k]), p.normal) > -1e-6);
    }
}

TEST_CASE("Atlas charts are padded: no two polygons' texels touch, even diagonally", "[cpu]") {
  Scene s = shapes();
  Atlas a = buildAtlas(s, 0.05);
  for (int y = 0; y + 1 < a.height; ++y)
    for (int x = 0; x + 1 < a.width; ++x) {
      std::uint32_t p = a.polygonOf[size_t(y) * a.width + x];
      if (p == kNoPolygon) continue;
      for (auto [dx, dy] : {std::pair{1, 0}, {0, 1}, {1, 1}}) {
        std::uint32_t q = a.polygonOf[size_t(y + dy) * a.width + x + dx];
        CHECK((q == kNoPolygon || q == p));
      }
    }
}

TEST_CASE("The --elements flag picks a texel size giving about that many elements", "[cpu]") {
  Scene s = shapes();
  for (size_t n : {200u, 3000u}) {
    Atlas a = buildAtlas(s, texelSizeForElements(s, n));
    CHECK(double(a.elements) == Approx(double(n)).epsilon(0.05));
  }
}

TEST_CASE("Shooter blocks at level k tile every element exactly once", "[cpu]") {
  Scene s = shapes();
  Atlas a = buildAtlas(s, 0.04);
  for (int level : {0, 1, 2, 3}) {
    std::vector<int> covered(a.polygonOf.size(), 0);
    for (const ShooterBlock& b : a.shooterBlocks(level)) {
      CHECK(b.rect.z <= (1 << level));
      CHECK(b.rect.w <= (1 << level));
      std::uint32_t owner = kNoPolygon;
      for (int y = b.rect.y; y < b.rect.y + b.rect.w; ++y)
        for (int x = b.rect.x; x < b.rect.x + b.rect.z; ++x) {
          std::uint32_t p = a.polygonOf[size_t(y) * a.width + x];
          ++covered[size_t(y) * a.width + x];
          if (p == kNoPolygon) continue;
          if (owner == kNoPolygon) owner = p;
          CHECK(p == owner);  // one block, one polygon
        }
    }
    for (size_t t = 0; t < covered.size(); ++t)
      if (a.polygonOf[t] != kNoPolygon) CHECK(covered[t] == 1);
  }
}

TEST_CASE("An atlas over the texture limit is refused with a texel size that fits", "[cpu]") {
  Scene s = shapes();
  CHECK_THROWS_WITH(buildAtlas(s, 1e-4, 4096), Catch::Contains("--texel-size"));
}
