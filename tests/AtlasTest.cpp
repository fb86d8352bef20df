#include <catch2/catch.hpp>
#include <cmath>

#include "cpu/ExactFormFactor.h"
#include "src/scene/Atlas.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
Scene shapes() {
  Scene s;
  int m = test::material(s, 0.5, 1.0);
  int o = s.addObject("shapes");
  s.addPolygon({{0, 0, 0}, {1, 0, 0}, {0.3, 0.8, 0}}, m, o);                           // triangle
  s.addPolygon(test::rectangle({0, 0, 1}, {1, 0, 0}, {0, 0.6, 0.8}, 1.3, 0.7), m, o);  // tilted quad
  Poly3 pentagon;
  for (int k = 0; k < 5; ++k) pentagon.push_back({2 + std::cos(k * 2 * M_PI / 5), 0.5, std::sin(k * 2 * M_PI / 5)});
  std::reverse(pentagon.begin(), pentagon.end());
  s.addPolygon(pentagon, m, o);
  return s;
}

// shapes() and charts over many polygons: a square wall of 6 x 6 quads cut into triangles, an
// L of coplanar quads (a concave union: its chart keeps the quads as parts) and a cylinder of
// 24 x 3 quads (curved: one chart per 30 degrees at --chart-angle 30 under --uv projection, a few
// LSCM charts under --uv auto).
Scene charted() {
  Scene s = shapes();
  int m = test::material(s, 0.5, 0.0), o = s.addObject("charted");
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      glm::dvec3 a(4 + i / 6.0, j / 6.0, 0), b = a + glm::dvec3(1 / 6.0, 0, 0), c = b + glm::dvec3(0, 1 / 6.0, 0),
                                             d = a + glm::dvec3(0, 1 / 6.0, 0);
      s.addPolygon({a, b, c}, m, o), s.addPolygon({a, c, d}, m, o);
    }
  for (auto [x, y] : {std::pair{0, 0}, {1, 0}, {0, 1}})
    s.addPolygon(test::rectangle({6 + 0.4 * x, 0.4 * y, 0}, {1, 0, 0}, {0, 1, 0}, 0.4, 0.4), m, o);
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 24; ++k) {
      auto at = [&](int kk, int jj) {
        return glm::dvec3(9 + std::cos(kk * M_PI / 12), jj / 3.0, std::sin(kk * M_PI / 12));
      };
      s.addPolygon({at(k, j), at(k, j + 1), at(k + 1, j + 1), at(k + 1, j)}, m, o);
    }
  return s;
}

// Per chart, the area of its polygons.
std::vector<double> chartAreas(const Scene& s, const Atlas& a) {
  std::vector<double> out(a.charts.size(), 0.0);
  for (std::size_t p = 0; p < s.polygons().size(); ++p) out[a.chartOf[p]] += s.polygons()[p].area;
  return out;
}
}  // namespace

TEST_CASE(
    "Projection charts join coplanar neighbours at angle 0 and curved ones at 30 degrees, one material and object each",
    "[cpu]") {
  Scene s = charted();
  const Atlas flat = buildAtlas(s, 0.05), curved = buildAtlas(s, 0.05, 16384, 0, 30, UvSource::Projection);
  // shapes' 3 polygons, the wall (one merged outline), the L (3 parts), 24 x 3 cylinder quads.
  CHECK(flat.charts.size() == 3 + 1 + 1 + 24);
  CHECK(curved.charts.size() < 3 + 1 + 1 + 24 / 2);
  const Chart& wall = flat.charts[flat.chartOf[3]];
  CHECK(wall.polygons.size() == 72);
  CHECK(wall.parts.size() == 1);  // the merged square: the grid an untessellated wall gets
  CHECK(wall.parts[0].size() == 4);
  CHECK(flat.charts[flat.chartOf[3 + 72]].parts.size() == 3);
  for (const Atlas* a : {&flat, &curved})
    for (const Chart& c : a->charts)
      for (int p : c.polygons) {
        CHECK(s.polygons()[std::size_t(p)].material == s.polygons()[std::size_t(c.polygon)].material);
        CHECK(s.polygons()[std::size_t(p)].object == s.polygons()[std::size_t(c.polygon)].object);
        CHECK(glm::dot(s.polygons()[std::size_t(p)].normal, c.frame.n) >
              std::cos((a == &flat ? 1e-3 : 30.0 * M_PI / 180)));
      }
}

TEST_CASE("Element pieces sum to their chart's polygon area in double, over multi-polygon and curved charts", "[cpu]") {
  Scene s = charted();
  for (double angle : {0.0, 30.0}) {
    Atlas a = buildAtlas(s, 0.037, 16384, 0, angle);
    std::vector<double> sum(a.charts.size(), 0.0);
    for (int y = 0; y < a.height; ++y)
      for (int x = 0; x < a.width; ++x) {
        const std::size_t t = std::size_t(y) * a.width + x;
        if (a.polygonOf[t] == kNoPolygon) continue;
        double pieces = 0;
        for (const Poly3& piece : a.elementShape(s, x, y)) pieces += area(piece);
        CHECK(pieces == Approx(a.positionArea[t].w).epsilon(1e-6));  // the element is its pieces
        sum[a.chartAt(t)] += pieces;
      }
    const std::vector<double> expected = chartAreas(s, a);
    for (std::size_t c = 0; c < sum.size(); ++c) CHECK(sum[c] == Approx(expected[c]).epsilon(1e-9));
  }
}

TEST_CASE("Atlas element areas sum to each chart's polygon area, partial texels included", "[cpu]") {
  Scene s = charted();
  for (double angle : {0.0, 30.0})
    for (double ts : {0.5, 0.11, 0.037}) {
      Atlas a = buildAtlas(s, ts, 16384, 0, angle);
      std::vector<double> sum(a.charts.size(), 0.0);
      for (size_t t = 0; t < a.polygonOf.size(); ++t)
        if (a.polygonOf[t] != kNoPolygon) sum[a.chartAt(t)] += a.positionArea[t].w;
      const std::vector<double> expected = chartAreas(s, a);
      for (size_t c = 0; c < sum.size(); ++c) CHECK(sum[c] == Approx(expected[c]).epsilon(1e-6));
    }
}

TEST_CASE("Atlas element centres lie on their chart and match their pieces' centroid", "[cpu]") {
  Scene s = charted();
  Atlas a = buildAtlas(s, 0.09);  // planar charts: the centre is in the pieces' plane, inside their union
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      size_t t = size_t(y) * a.width + x;
      if (a.polygonOf[t] == kNoPolygon) continue;
      const ScenePolygon& p = s.polygons()[a.polygonOf[t]];
      glm::dvec3 c(a.positionArea[t]), weighted(0.0);
      CHECK(std::abs(glm::dot(c - p.vertices[0], p.normal)) < 1e-5);
      double total = 0;
      bool inside = false;
      for (const Poly3& cut : a.elementShape(s, x, y)) {
        Poly2 flat;
        const PlaneFrame f = planeFrame(cut, p.normal);
        for (auto& v : cut) flat.push_back(f.project(v));
        weighted += area(cut) * f.lift(centroid(flat)), total += area(cut);
        // A convex piece holds c if c is inside every edge's half-plane.
        bool in = true;
        for (size_t k = 0; k < cut.size(); ++k)
          in = in && glm::dot(glm::cross(cut[(k + 1) % cut.size()] - cut[k], c - cut[k]), p.normal) > -1e-6;
        inside = inside || in;
      }
      CHECK(total == Approx(a.positionArea[t].w).epsilon(1e-5));
      CHECK(glm::length(weighted / total - c) < 1e-5);
      // One piece: its centroid is inside it (convex). Several: the union of a chart's pieces
      // in a texel need not be convex, so only one piece's element is checked.
      if (a.elementShape(s, x, y).size() == 1) CHECK(inside);
    }
}

// No gutters (src/scene/AtlasPacker.h): charts may touch, but their rectangles never overlap,
// and every texel of a chart's rectangle that holds an element is that chart's.
TEST_CASE("Atlas charts' rectangles lie in the atlas without overlapping, and hold only their own elements", "[cpu]") {
  Scene s = charted();
  for (double angle : {0.0, 30.0}) {
    Atlas a = buildAtlas(s, 0.05, 16384, 0, angle);
    std::vector<int> owner(a.polygonOf.size(), -1);
    for (std::size_t c = 0; c < a.charts.size(); ++c) {
      const Chart& chart = a.charts[c];
      REQUIRE(chart.origin.x >= 0);
      REQUIRE(chart.origin.y >= 0);
      REQUIRE(chart.origin.x + chart.size.x <= a.width);
      REQUIRE(chart.origin.y + chart.size.y <= a.height);
      for (int j = 0; j < chart.size.y; ++j)
        for (int i = 0; i < chart.size.x; ++i) {
          const std::size_t t = std::size_t(chart.origin.y + j) * a.width + std::size_t(chart.origin.x + i);
          CHECK(owner[t] == -1);  // one rectangle a texel
          owner[t] = int(c);
          CHECK((a.chartAt(t) == kNoPolygon || a.chartAt(t) == c));
        }
    }
    for (std::size_t t = 0; t < owner.size(); ++t)
      if (a.polygonOf[t] != kNoPolygon) CHECK(owner[t] >= 0);
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
  Scene s = charted();
  Atlas a = buildAtlas(s, 0.04);
  for (int level : {0, 1, 2, 3}) {
    std::vector<int> covered(a.polygonOf.size(), 0);
    for (const ShooterBlock& b : a.shooterBlocks(level)) {
      CHECK(b.rect.z <= (1 << level));
      CHECK(b.rect.w <= (1 << level));
      std::uint32_t owner = kNoPolygon;
      for (int y = b.rect.y; y < b.rect.y + b.rect.w; ++y)
        for (int x = b.rect.x; x < b.rect.x + b.rect.z; ++x) {
          std::uint32_t p = a.chartAt(size_t(y) * a.width + x);
          ++covered[size_t(y) * a.width + x];
          if (p == kNoPolygon) continue;
          if (owner == kNoPolygon) owner = p;
          CHECK(p == owner);  // one block, one chart
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

TEST_CASE("A block's outline is one convex piece where its pieces tile a convex region, shooting what they shoot",
          "[cpu]") {
  const Scene s = charted();
  const Atlas a = buildAtlas(s, 0.05, 16384, 0, 30, UvSource::Projection);
  int lMerged = 0, curvedMerged = 0, compared = 0;
  for (std::uint32_t c = 0; c < a.charts.size(); ++c) {
    const Chart& chart = a.charts[c];
    const glm::ivec2 o = chart.origin, n = chart.size, h = glm::max(n / 2, 1);
    // The whole chart and its halves: the L of three quads (concave) has two halves of two quads
    // side by side (convex), whichever way its grid lies; the cylinder's charts are curved.
    for (const glm::ivec4 r : {glm::ivec4(o, n), glm::ivec4(o, n.x, h.y), glm::ivec4(o.x, o.y + h.y, n.x, n.y - h.y),
                               glm::ivec4(o, h.x, n.y), glm::ivec4(o.x + h.x, o.y, n.x - h.x, n.y)}) {
      const std::vector<Poly3> pieces = a.blockShape(s, r), outline = a.blockOutline(s, r);
      if (pieces.size() < 2) continue;
      CAPTURE(c, pieces.size(), chart.polygons.size());
      const bool l = chart.planar && chart.polygons.size() == 3;
      if (l && r == glm::ivec4(o, n)) CHECK(outline == pieces);  // concave: kept
      if (l) lMerged += outline.size() == 1;
      if (!chart.planar) curvedMerged += outline != pieces;
      double whole = 0, outlined = 0;
      for (const Poly3& p : pieces) whole += area(p);
      for (const Poly3& p : outline) outlined += area(p);
      CHECK(outlined == Approx(whole).epsilon(1e-12));
      // What a receiver in front of it sees: the contour integral is linear in the shape.
      const glm::dvec3 front = glm::normalize(newellNormal(pieces[0]));
      const glm::dvec3 at = pieces[0][0] + 0.3 * front + glm::dvec3(0.05, 0.02, 0.01);
      double F = 0, G = 0;
      for (const Poly3& p : pieces) F += cpu::pointToPolygon(at, -front, p, newellNormal(p));
      for (const Poly3& p : outline) G += cpu::pointToPolygon(at, -front, p, newellNormal(p));
      CHECK(G == Approx(F).epsilon(1e-10));
      compared += F > 0;
    }
  }
  CHECK(lMerged == 2);
  CHECK(curvedMerged == 0);
  CHECK(compared > 10);
}
