// Charts over many polygons (issue 29, src/scene/Charts.h): a tessellated surface solves as
// the untessellated one, shows no seam at its polygons' edges, and shoots no more often.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>

#include "src/output/Renderer.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// rectangle(o, u, v, 1, 1) cut into n x n quads, each split into two triangles (same front side).
void addTessellated(Scene& s, glm::dvec3 o, glm::dvec3 u, glm::dvec3 v, double w, double h, int n, int m, int obj) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 a = o + u * (w * i / n) + v * (h * j / n), b = a + u * (w / n), c = b + v * (h / n),
                       d = a + v * (h / n);
      s.addPolygon({a, b, c}, m, obj), s.addPolygon({a, c, d}, m, obj);
    }
}

// test::cube with every face cut into n x n quads of two triangles.
Scene tessellatedCube(double rho, double E, int n) {
  Scene s;
  const int wall = test::material(s, rho, E), o = s.addObject("box");
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1), O(0.0);
  const std::pair<glm::dvec3, std::pair<glm::dvec3, glm::dvec3>> faces[6] = {
      {O, {Z, X}}, {Y, {X, Z}}, {O, {X, Y}}, {Z, {Y, X}}, {O, {Y, Z}}, {X, {Z, Y}}};  // as test::cube
  for (auto& [origin, axes] : faces) addTessellated(s, origin, axes.first, axes.second, 1, 1, n, wall, o);
  return s;
}

ProgressiveSettings fastPlan(double converge) {
  ProgressiveSettings p;
  p.shootLevel = kAutoShootLevel;
  p.itemResolution = kAutoItemResolution;
  p.projection = Projection::Hemicube;
  p.itemSubdivision = 0;
  p.stop.targetConvergence = converge;
  return p;
}

// A 1 x 1 floor (y = 0) under a 0.2 x 0.2 lamp at height 0.5; the floor a quad, or cut into
// n x n quads of two triangles (n = 0: the quad).
Scene litFloor(int n) {
  Scene s;
  const int grey = test::material(s, 0.5, 0.0), lamp = test::material(s, 0.0, 10.0);
  const int floor = s.addObject("floor"), light = s.addObject("lamp");
  const glm::dvec3 X(1, 0, 0), Z(0, 0, 1);
  if (n == 0)
    s.addPolygon(test::rectangle({0, 0, 0}, Z, X, 1, 1), grey, floor);
  else
    addTessellated(s, {0, 0, 0}, Z, X, 1, 1, n, grey, floor);
  s.addPolygon(test::rectangle({0.3, 0.5, 0.4}, X, Z, 0.2, 0.2), lamp, light);  // faces down
  return s;
}

double luminanceAt(const Image& im, int x, int y) {
  const float* p = &im.rgb[(std::size_t(y) * im.width + x) * 3];
  return luminance(glm::dvec3(p[0], p[1], p[2]));
}

}  // namespace

TEST_CASE("A closed box of tessellated walls solves as the untessellated box: one chart a wall, same elements, same B",
          "[heavy][gl][charts]") {
  const double rho = 0.5;
  Scene plain = test::cube(rho, 1.0), cut = tessellatedCube(rho, 1.0, 8);
  REQUIRE(cut.polygons().size() == 6 * 8 * 8 * 2);
  const test::Solved a = test::solve(plain, 1.0 / 8, fastPlan(0.9995)), b = test::solve(cut, 1.0 / 8, fastPlan(0.9995));
  CHECK(b.atlas.charts.size() == 6);
  CHECK(b.atlas.elements == a.atlas.elements);
  const double meanA = test::object(a, "box").mean.x, meanB = test::object(b, "box").mean.x, exact = 1 / (1 - rho);
  INFO("untessellated " << meanA << " after " << a.status.shots << " shots, tessellated " << meanB << " after "
                        << b.status.shots << "; E/(1-rho) " << exact);
  CHECK(meanB == Approx(meanA).epsilon(1e-4));  // float noise: the same grid, perhaps turned
  CHECK(meanB == Approx(exact).epsilon(0.001));
  CHECK(b.status.shots == Approx(a.status.shots).epsilon(0.05));
}

TEST_CASE("A floor of 32 x 32 triangle pairs is one chart: shots to 90 % as for one quad, no step at the cuts",
          "[gl][charts]") {
  const Scene quad = litFloor(0), cut = litFloor(32);
  const Camera top{{0.5, 0.4, 0.5}, {0.5, 0.0, 0.5}, {0, 0, 1}, 90.0};  // under the lamp: x in [0.1, 0.9] in view
  const test::Solved a = test::solve(quad, 1.0 / 24, fastPlan(0.9), &top),
                     b = test::solve(cut, 1.0 / 24, fastPlan(0.9), &top);
  CHECK(b.atlas.charts.size() == 2);
  INFO("shots: quad " << a.status.shots << ", 2048 triangles " << b.status.shots);
  CHECK(double(b.status.shots) == Approx(double(a.status.shots)).epsilon(0.05));
  // Along every image row over the floor, the luminance step between neighbouring pixels at a
  // cut (every 1/32 along x) is no larger than the largest step elsewhere in that row: the
  // lookup blends across the cut as within a polygon.
  const Image& im = b.view;
  const double half = 0.4 * std::tan(glm::radians(45.0));  // half the view's side at the floor
  auto column = [&](double x) {
    return int(std::floor((0.5 + half - x) / (2 * half) * im.width));
  };  // x runs right to left
  int rows = 0;
  for (int y = im.height / 2 - 20; y < im.height / 2 + 20; ++y) {
    double atCut = 0, elsewhere = 0;
    for (int x = column(0.85); x < column(0.15); ++x) {
      const double step = std::abs(luminanceAt(im, x, y) - luminanceAt(im, x - 1, y));
      bool cutHere = false;
      for (int k = 1; k < 32; ++k) cutHere = cutHere || column(k / 32.0) == x || column(k / 32.0) == x - 1;
      (cutHere ? atCut : elsewhere) = std::max(cutHere ? atCut : elsewhere, step);
    }
    CHECK(atCut <= elsewhere * 1.01);
    ++rows;
  }
  CHECK(rows == 40);
}

namespace {
// A vertical tube (radius 1, height 1, 48 x 4 quads facing in) standing on a 2.4 x 2.4 floor,
// lit by a 0.4 x 0.4 lamp at height 0.9 facing down.
Scene litTube() {
  Scene s;
  const int grey = test::material(s, 0.6, 0.0), lamp = test::material(s, 0.0, 5.0);
  const int tube = s.addObject("tube"), floor = s.addObject("floor"), light = s.addObject("lamp");
  auto at = [](int k, int j) { return glm::dvec3(std::cos(k * M_PI / 24), j / 4.0, std::sin(k * M_PI / 24)); };
  for (int j = 0; j < 4; ++j)
    for (int k = 0; k < 48; ++k) s.addPolygon({at(k, j), at(k + 1, j), at(k + 1, j + 1), at(k, j + 1)}, grey, tube);
  const glm::dvec3 X(1, 0, 0), Z(0, 0, 1);
  s.addPolygon(test::rectangle({-1.2, 0, -1.2}, Z, X, 2.4, 2.4), grey, floor);
  s.addPolygon(test::rectangle({-0.2, 0.9, -0.2}, X, Z, 0.4, 0.4), lamp, light);
  return s;
}

test::Solved solveCharts(const Scene& s, double texel, double angle, const ProgressiveSettings& p) {
  test::Solved out;
  test::backend();
  out.atlas = buildAtlas(s, texel, 16384, 0, angle);
  SolverState state(s, out.atlas);
  ProgressiveSolver solver(state, p);
  while (!out.status.done) out.status = solver.advance(64);
  out.B = state.readRadiosity();
  out.objects = objectRadiosity(s, out.atlas, out.B);
  return out;
}
}  // namespace

TEST_CASE(
    "Curved charts at --chart-angle 30 on a tessellated tube: a tenth of the charts, every polygon's area covered "
    "once, the "
    "tube's radiosity as with a chart per facet",
    "[heavy][gl][charts]") {
  const Scene s = litTube();
  const Atlas atlas = buildAtlas(s, 0.05, 16384, 0, 30);
  CHECK(atlas.charts.size() * 10 < s.polygons().size());
  // Each curved chart's parts are its polygons: the pieces of part k over all texels sum to its area.
  double pieces = 0, polygons = 0;
  for (const Chart& c : atlas.charts) {
    const std::vector<Poly3> all = atlas.blockShape(s, glm::ivec4(c.origin, c.size));
    double sum = 0;
    for (const Poly3& piece : all) sum += area(piece);
    double expected = 0;
    for (int p : c.polygons) expected += s.polygons()[std::size_t(p)].area;
    CHECK(sum == Approx(expected).epsilon(1e-12));
    pieces += sum, polygons += expected;
    for (int y = c.origin.y; y < c.origin.y + c.size.y; ++y)  // texel by texel: the same area, in double
      for (int x = c.origin.x; x < c.origin.x + c.size.x; ++x)
        for (const Poly3& piece : atlas.elementShape(s, x, y)) sum -= area(piece);
    CHECK(std::abs(sum) < 1e-12 * expected);
  }
  CHECK(pieces == Approx(s.totalArea()).epsilon(1e-12));
  ProgressiveSettings p = fastPlan(0.95);
  p.shootLevel = 2;
  const test::Solved charts = solveCharts(s, 0.05, 30, p), facets = solveCharts(s, 0.03, 0, p);
  const double curved = test::object(charts, "tube").mean.x, reference = test::object(facets, "tube").mean.x;
  INFO("tube mean B: " << curved << " with " << charts.atlas.charts.size() << " charts, " << charts.atlas.elements
                       << " elements; " << reference << " with a chart per facet column, " << facets.atlas.elements
                       << " elements");
  // Measured 0.14 % apart (0.06859 against 0.06850 at 0.95 convergence): the pieces' exact shapes
  // and mean normals lose nothing to the projection; 1 % leaves room for the two discretisations.
  CHECK(curved == Approx(reference).epsilon(0.01));
  CHECK(test::object(charts, "floor").mean.x == Approx(test::object(facets, "floor").mean.x).epsilon(0.01));
}
