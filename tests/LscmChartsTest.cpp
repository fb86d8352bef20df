// Curved charts under LSCM (issue 29, src/scene/Lscm.h): a smooth disc of up to 90 degrees of
// normals is one chart under its conformal map, scaled to its surface area; a closed surface, a
// non-manifold fan or a mirrored neighbour is never one LSCM chart and still ends in charts that
// cover every polygon once; flat scenes keep their projection charts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>

#include "src/scene/Charts.h"
#include "src/scene/Lscm.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// The first `stacks` of a 24 x 12 UV sphere's (15 degrees each) facing out, from the south pole
// (its triangles first: the first chart's seed); 6 stacks are the lower hemisphere.
Scene sphereCap(int stacks) {
  Scene sphere;
  const int grey = test::material(sphere, 0.5, 0.0);
  test::addSphere(sphere, glm::dvec3(0.0), 1.0, 24, 12, grey, sphere.addObject("sphere"));
  Scene s;
  test::material(s, 0.5, 0.0);
  const int obj = s.addObject("hemisphere");
  for (const ScenePolygon& p : sphere.polygons())
    if (std::all_of(p.vertices.begin(), p.vertices.end(),
                    [&](const glm::dvec3& v) { return v.y <= -std::cos(stacks * M_PI / 12) + 1e-12; }))
      s.addPolygon(p.vertices, 0, obj);
  return s;
}

// The LSCM of every polygon of `s`, fanned, vertices welded by position.
LscmMap lscmOf(const Scene& s) {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<int, 3>> triangles;
  for (const ScenePolygon& p : s.polygons())
    for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
      std::array<int, 3> t{};
      for (std::size_t i = 0; i < 3; ++i) {
        const glm::dvec3 v = p.vertices[i == 0 ? 0 : k + i - 1];
        auto it =
            std::find_if(positions.begin(), positions.end(), [&](glm::dvec3 q) { return glm::length(q - v) < 1e-9; });
        t[i] = int(it - positions.begin());
        if (it == positions.end()) positions.push_back(v);
      }
      triangles.push_back(t);
    }
  return lscmMap(positions, triangles);
}

// How many charts hold each polygon (each part's polygon once per chart).
std::vector<int> chartsPerPolygon(const Scene& s, const std::vector<ChartGroup>& charts) {
  std::vector<int> n(s.polygons().size(), 0);
  for (const ChartGroup& g : charts)
    for (int p : g.polygons) ++n[std::size_t(p)];
  return n;
}

}  // namespace

TEST_CASE(
    "A tessellated sphere cap of 150 degrees is one LSCM chart: its chart area is its surface area and no "
    "triangle's texel density is off the chart's by more than the bound (a hemisphere's map holds it too), where "
    "projection needs several charts",
    "[cpu][charts]") {
  const LscmMap half = lscmOf(sphereCap(6));
  INFO("the hemisphere's map: outcome " << int(half.outcome) << ", area distortion " << half.areaDistortion
                                        << ", anisotropy " << half.anisotropy);
  CHECK(half.outcome == LscmOutcome::Mapped);
  CHECK(half.areaDistortion == Approx(2.03).epsilon(0.01));
  // A chart's normals lie within 90 degrees of its seed's, the pole triangle's (tilted 7.5 degrees).
  const Scene s = sphereCap(5);
  REQUIRE(s.polygons().size() == 24 * 5);
  const std::vector<ChartGroup> charts = groupCharts(s, kDefaultChartAngle);
  REQUIRE(charts.size() == 1);
  const ChartGroup& g = charts[0];
  REQUIRE(g.uv.size() == g.parts.size());
  CHECK(!g.planar);
  double surface = 0, mapped = 0, worst = 1;
  for (std::size_t k = 0; k < g.parts.size(); ++k) {
    const double a = area(g.parts[k]), u = signedArea(g.uv[k]);
    surface += a, mapped += u;
    worst = std::max({worst, u / a, a / u});
  }
  INFO("worst texel density against the chart's: " << worst);
  CHECK(surface == Approx(s.totalArea()).epsilon(1e-12));
  CHECK(mapped == Approx(surface).epsilon(1e-12));
  CHECK(worst <= kMaxLscmAreaDistortion);
  CHECK(worst > 1.05);  // a sphere's conformal map cannot be area-preserving: the check above can fail
  CHECK(groupCharts(s, kDefaultChartAngle, ChartMap::Projection).size() >= 4);
}

TEST_CASE(
    "A closed sphere is no disc: LSCM refuses it whole, and its charts hold every facet exactly once with no chart "
    "over more than 90 degrees of normals",
    "[cpu][charts]") {
  Scene s;
  test::addSphere(s, glm::dvec3(0.0), 1.0, 16, 8, test::material(s, 0.5, 0.0), s.addObject("sphere"));
  CHECK(lscmOf(s).outcome == LscmOutcome::NotDisc);
  const std::vector<ChartGroup> charts = groupCharts(s, kDefaultChartAngle);
  CHECK(charts.size() >= 2);
  CHECK(chartsPerPolygon(s, charts) == std::vector<int>(s.polygons().size(), 1));
  std::size_t lscm = 0;
  for (const ChartGroup& g : charts) {
    lscm += !g.uv.empty();
    for (int p : g.polygons) CHECK(glm::dot(s.polygons()[std::size_t(p)].normal, g.axis) > 0);
  }
  CHECK(lscm >= 2);
}

TEST_CASE(
    "A non-manifold fan and a shallow ring around a hole are no discs: LSCM refuses them and they keep their "
    "projection charts",
    "[cpu][charts]") {
  // Two triangles wound against each other over one edge: no orientable mesh.
  CHECK(lscmMap({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0.1}}, {{{0, 1, 2}}, {{0, 1, 3}}}).outcome ==
        LscmOutcome::NotDisc);
  Scene s;
  const int grey = test::material(s, 0.5, 0.0), obj = s.addObject("shape");
  SECTION("three quads 10 degrees apart on one spine edge") {
    for (int i = 0; i < 3; ++i) {
      const double a = (i - 1) * 10 * M_PI / 180;
      s.addPolygon(test::rectangle({0, 0, 0}, {0, 0, 1}, {std::cos(a), std::sin(a), 0}, 1, 1), grey, obj);
    }
  }
  SECTION("a ring of 16 quads sloping 8.5 degrees (a cone around a hole: two boundary loops)") {
    auto at = [](int i, double r) {
      const double phi = 2 * M_PI * i / 16;
      return glm::dvec3(r * std::cos(phi), r * std::sin(phi), 0.15 * r);
    };
    for (int i = 0; i < 16; ++i) s.addPolygon({at(i, 1), at(i + 1, 1), at(i + 1, 2), at(i, 2)}, grey, obj);
  }
  const std::vector<ChartGroup> lscm = groupCharts(s, kDefaultChartAngle),
                                projection = groupCharts(s, kDefaultChartAngle, ChartMap::Projection);
  REQUIRE(lscm.size() == projection.size());
  for (std::size_t c = 0; c < lscm.size(); ++c) {
    CHECK(lscm[c].uv.empty());
    CHECK(lscm[c].polygons == projection[c].polygons);
  }
  CHECK(chartsPerPolygon(s, lscm) == std::vector<int>(s.polygons().size(), 1));
}

TEST_CASE("The flat Cornell box's charts are its projection charts, part for part", "[cpu][charts]") {
  const Scene s = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  for (double angle : {0.0, kDefaultChartAngle}) {
    const std::vector<ChartGroup> lscm = groupCharts(s, angle),
                                  projection = groupCharts(s, angle, ChartMap::Projection);
    REQUIRE(lscm.size() == projection.size());
    for (std::size_t c = 0; c < lscm.size(); ++c) {
      CHECK(lscm[c].uv.empty());
      CHECK(lscm[c].polygons == projection[c].polygons);
      CHECK(lscm[c].parts == projection[c].parts);
      CHECK(lscm[c].axis == projection[c].axis);
    }
  }
}
