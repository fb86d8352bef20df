// Issue 29's texel use: the solve's atlas packs charts without gutters by best fit
// (src/scene/AtlasPacker.h), each chart's grid along its outline's minimum-area rectangle
// (src/base/MinAreaRect.h); the lightmap, its coordinates clamped to its charts' cells (Lightmap.h),
// needs no gutters either.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "src/base/MinAreaRect.h"
#include "src/output/Lightmap.h"
#include "src/scene/Atlas.h"
#include "src/scene/AtlasPacker.h"
#include "src/scene/AtlasUse.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
glm::dvec3 turnedXy(glm::dvec2 p, double angle, glm::dvec3 at) {
  return at +
         glm::dvec3(p.x * std::cos(angle) - p.y * std::sin(angle), p.x * std::sin(angle) + p.y * std::cos(angle), 0);
}

// n separate small charts on the floor, turned at random: triangles, thin strips and quads cut
// along a diagonal (the seed's longest edge then runs across the chart). Fixed seed.
Scene smallCharts(int n) {
  Scene s;
  const int m = test::material(s, 0.5, 0.0), o = s.addObject("pieces");
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    const glm::dvec3 at(2.0 * (k % 64), 2.0 * (k / 64), 0);
    const double angle = 2 * M_PI * unit(rng), w = 0.2 + 0.8 * unit(rng), h = 0.2 + 0.8 * unit(rng);
    auto p = [&](double x, double y) { return turnedXy({x, y}, angle, at); };
    switch (k % 3) {
      case 0:
        s.addPolygon({p(0, 0), p(w, 0), p(w * unit(rng), h)}, m, o);
        break;
      case 1:
        s.addPolygon({p(0, 0), p(w + 0.5, 0), p(w + 0.5, 0.06), p(0, 0.06)}, m, o);
        break;
      default:
        s.addPolygon({p(0, 0), p(w, 0), p(w, h)}, m, o), s.addPolygon({p(0, 0), p(w, h), p(0, h)}, m, o);
    }
  }
  return s;
}
}  // namespace

TEST_CASE("Many small charts of mixed shapes fill >= 75 % of the solve's atlas and of the lightmap", "[cpu]") {
  const Scene s = smallCharts(1500);
  const Atlas a = buildAtlas(s, texelSizeForElements(s, 30000));
  const AtlasUse use = atlasUse(a);
  INFO(a.charts.size() << " charts, " << a.elements << " elements, " << a.width << " x " << a.height << ", cell use "
                       << use.cellUse() << ", packing " << use.packing());
  CHECK(a.charts.size() == 1500);
  CHECK(use.texelUse() >= 0.75);
  CHECK(use.packing() >= 0.95);
  // The lightmap: 86.6 % without gutters; 1-texel gutters around charts of ~20 elements bound it
  // (Lightmap.h): 41.3 %.
  const Lightmap map = buildLightmap(a, std::vector<glm::vec4>(a.polygonOf.size(), glm::vec4(0.0f)));
  INFO("lightmap " << map.width << " x " << map.height << ", texel use " << map.texelUse());
  CHECK(map.texelUse() >= 0.75);
}

TEST_CASE("A rectangle turned in its plane and cut along its diagonal gets a tight grid", "[cpu]") {
  // Folded 2 degrees along the diagonal: one curved chart whose seed, a triangle, has the
  // diagonal as its longest edge (the frame the grid was laid along before).
  Scene s;
  const int m = test::material(s, 0.5, 0.0), o = s.addObject("strip");
  const double angle = 0.65, fold = 2 * M_PI / 180;
  const glm::dvec3 a = turnedXy({0, 0}, angle, {}), b = turnedXy({1, 0}, angle, {}), c = turnedXy({1, 0.3}, angle, {}),
                   d0 = turnedXy({0, 0.3}, angle, {});
  const glm::dvec3 mid = 0.5 * (a + c),
                   across = d0 - mid - glm::dot(d0 - mid, glm::normalize(c - a)) * glm::normalize(c - a);
  const glm::dvec3 d = d0 + glm::dvec3(0, 0, std::sin(fold) * glm::length(across)) - across * (1 - std::cos(fold));
  s.addPolygon({a, b, c}, m, o), s.addPolygon({a, c, d}, m, o);
  const Atlas atlas = buildAtlas(s, 0.01, 16384, 0, 30);
  REQUIRE(atlas.charts.size() == 1);
  const glm::ivec2 size = atlas.charts[0].size;
  INFO("chart " << size.x << " x " << size.y);
  CHECK(std::max(size.x, size.y) <= 101);
  CHECK(std::min(size.x, size.y) <= 31);
  CHECK(double(atlas.elements) >= 0.97 * size.x * size.y);
}

TEST_CASE("The minimum-area rectangle of a turned rectangle's points is that rectangle", "[cpu]") {
  std::vector<glm::dvec2> points;
  for (glm::dvec2 p : {glm::dvec2(0, 0), {2, 0}, {2, 0.5}, {0, 0.5}, {1, 0.25}, {0.3, 0.1}})
    points.push_back(glm::dvec2(turnedXy(p, 0.4, {3, -1, 0})));
  const MinAreaRect r = minAreaRect(points);
  CHECK(r.area == Approx(1.0));
  CHECK(std::abs(std::abs(glm::dot(r.axis, glm::dvec2(std::cos(0.4), std::sin(0.4)))) - 0.5) == Approx(0.5));
}

TEST_CASE("Best-fit packing places every rectangle once, inside the strip, in steps linear in their count",
          "[heavy][cpu]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> side(1, 12), longSide(1, 60);
  std::vector<std::size_t> steps;
  for (int n : {2000, 20000}) {
    std::vector<glm::ivec2> sizes;
    for (int i = 0; i < n; ++i)
      sizes.push_back(i % 10 ? glm::ivec2(side(rng), side(rng)) : glm::ivec2(longSide(rng), side(rng)));
    const RectLayout l = packAtlasCharts(sizes, 16384);
    std::vector<char> used(std::size_t(l.width) * l.height, 0);
    double area = 0;
    for (int i = 0; i < n; ++i) {
      const glm::ivec2 s = l.turned[i] ? glm::ivec2(sizes[i].y, sizes[i].x) : sizes[i], o = l.origins[i];
      REQUIRE((o.x >= 0 && o.y >= 0 && o.x + s.x <= l.width && o.y + s.y <= l.height));
      for (int y = o.y; y < o.y + s.y; ++y)
        for (int x = o.x; x < o.x + s.x; ++x) REQUIRE(used[std::size_t(y) * l.width + x]++ == 0);
      area += double(s.x) * s.y;
    }
    CHECK(area / (double(l.width) * l.height) >= 0.95);
    // A step places a rectangle or removes a skyline segment (at most two a placement), each
    // O(log n) in ordered sets: O(n log n) in all, as the 10x count shows.
    const RectLayout one = packBestFit(sizes, l.width);
    CHECK(one.steps <= std::size_t(3 * n));
    steps.push_back(one.steps);
  }
  CHECK(double(steps[1]) <= 12.0 * double(steps[0]));
}

TEST_CASE("Every point of every polygon looks up texels of its own chart's rectangle", "[cpu]") {
  const Scene s = smallCharts(300);
  const Atlas a = buildAtlas(s, texelSizeForElements(s, 5000));
  for (std::size_t p = 0; p < s.polygons().size(); ++p) {
    const Chart& c = a.charts[a.chartOf[p]];
    const auto& v = s.polygons()[p].vertices;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const glm::dvec3 points[2] = {v[k], 0.5 * (v[k] + v[(k + 1) % v.size()])};
      for (const glm::dvec3& q : points) {
        const glm::dvec2 t = a.atlasCoord(int(p), q) - glm::dvec2(c.origin);
        CHECK(t.x >= -1e-6);
        CHECK(t.y >= -1e-6);
        CHECK(t.x <= c.size.x + 1e-6);
        CHECK(t.y <= c.size.y + 1e-6);
      }
    }
    // The centroid's texel holds an element of this chart (a convex polygon covers its centroid).
    glm::dvec3 centre(0.0);
    for (auto& q : v) centre += q / double(v.size());
    const glm::ivec2 t(glm::floor(a.atlasCoord(int(p), centre)));
    CHECK(a.chartAt(std::size_t(t.y) * a.width + std::size_t(t.x)) == a.chartOf[p]);
  }
}

TEST_CASE("A lone long chart lies along a strip as wide as it is long", "[cpu]") {
  const RectLayout l = packAtlasCharts({glm::ivec2(3, 1000)}, 16384);
  CHECK(l.width == 1000);
  CHECK(l.height == 3);
  CHECK(l.turned[0] == 1);
}
