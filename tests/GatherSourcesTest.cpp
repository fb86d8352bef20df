// What the near final gather knows of each element (src/output/GatherSources.h): a border element of
// a chart is a cut cell, so its profile must follow its piece, not its cell; and its slope must
// follow light that steepens toward a crease or a contact without passing its neighbours.
#include <catch2/catch.hpp>

#include <cmath>

#include "src/output/GatherSources.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Subdivide.h"
#include "tests/support/Files.h"

using namespace hemirad;

namespace {

// A unit square in the y = 0 plane at texel size `texel`, sending light(x) from each element: what
// gatherSources makes of it, per node of its shooter tree.
struct SquareSources {
  Atlas atlas;
  ShooterTree tree;
  std::vector<glm::vec4> sources;
};

template <class Light>
SquareSources squareSources(const std::string& name, double texel, Light light) {
  const std::string path = test::writeScene(
      name, "mtllib m.mtl\nusemtl w\nv 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n", "newmtl w\nKd 0.5 0.5 0.5\n");
  SquareSources s{buildAtlas(loadScene(path), texel), {}, {}};
  s.tree = buildShooterTree(s.atlas, s.atlas.shooterBlocks(4), 4);
  std::vector<glm::vec4> sent(s.atlas.positionArea.size(), glm::vec4(0.0f));
  for (std::size_t t = 0; t < sent.size(); ++t)
    if (s.atlas.positionArea[t].w > 0) sent[t] = glm::vec4(glm::vec3(float(light(s.atlas.positionArea[t].x))), 0.0f);
  s.sources = gatherSources(s.atlas, s.tree.nodes, sent);
  return s;
}

}  // namespace

TEST_CASE(
    "The near gather's element profiles follow a linear light across every piece: border cells cut by the "
    "polygon's edge included",
    "[cpu]") {
  // A unit square at texel size 0.3: 4 x 4 cells centred on it, so the outer ones are cut to 0.2
  // and their centroids lie 0.25 from the next ones, not a cell. The light sent grows linearly
  // along x, so each element's change across its piece is exact: 2 b hu.x over its own light.
  // Before, a border element's change was taken per cell step from a centroid 0.25 away (17 %
  // short) and spread over the whole cell.
  const double a = 1, b = 2;
  const auto [atlas, tree, sources] = squareSources("linear_light", 0.3, [&](double x) { return a + b * x; });
  int elements = 0, border = 0;
  for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
    const glm::ivec4 r = tree.nodes[n].rect;
    if (r.z != 1 || r.w != 1 || tree.nodes[n].polygon == kNoPolygon) continue;
    const glm::vec4 p = atlas.positionArea[std::size_t(r.y) * atlas.width + r.x];
    const glm::vec4 hu = sources[n * 4 + 2], hv = sources[n * 4 + 3];
    const double own = a + b * p.x, pieceArea = 4 * glm::length(glm::vec3(hu)) * glm::length(glm::vec3(hv));
    INFO("element at " << p.x << ", " << p.z << ": area " << p.w << ", changes " << hu.w << ", " << hv.w);
    CHECK(std::abs(pieceArea - p.w) < 1e-6);  // the half-axes span the piece
    CHECK(std::abs(hu.w - 2 * b * hu.x / own) < 1e-5);
    CHECK(std::abs(hv.w - 2 * b * hv.x / own) < 1e-5);
    ++elements;
    border += p.w < 0.3 * 0.3 - 1e-6;
  }
  CHECK(elements == 16);
  CHECK(border == 12);
}

TEST_CASE(
    "The near gather's element profiles follow light that steepens toward a contact or a crease closer than minmod "
    "and the one-sided change, and stay within their neighbours",
    "[cpu]") {
  // A unit square at texel size 0.1 (10 x 10 whole cells), the light sent sqrt(x): it falls ever
  // faster toward x = 0, as a floor's into the shadow at a block's base or a wall's toward the
  // ceiling. A piece's profile reaches its side toward x = 0 at own (1 - change / 2). Inside,
  // minmod takes the flatter side's change and leaves that side too bright; the limited central
  // change (centralLimitedSlope) is the parabola's through the three means, and never passes the
  // neighbour's own light. At the chart's edge the one-sided change to the next is the flatter
  // too; the parabola through the next two (edgeSlope) is steeper.
  const double h = 0.1;
  auto light = [](double x) { return std::sqrt(x); };
  const auto [atlas, tree, sources] = squareSources("steepening_light", h, light);
  int inner = 0, edge = 0;
  double worst = 0, worstMinmod = 0;
  for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
    const glm::ivec4 r = tree.nodes[n].rect;
    if (r.z != 1 || r.w != 1 || tree.nodes[n].polygon == kNoPolygon) continue;
    const double x = atlas.positionArea[std::size_t(r.y) * atlas.width + r.x].x;
    if (x > 1 - h) continue;  // the far edge: the light flattens there
    const glm::vec4 hu = sources[n * 4 + 2], hv = sources[n * 4 + 3];
    const double change = std::abs(hu.x) > std::abs(hv.x) ? hu.w : hv.w;  // across the piece along x
    const double own = light(x), side = own * (1 - std::abs(change) / 2), truth = light(x - h / 2);
    const double flatter = own - (light(x + h) - own) / 2;  // minmod's inside, the one-sided change's at the edge
    INFO("element at x " << x << ": its side toward 0 " << side << ", the flatter change's " << flatter
                         << ", the light's " << truth);
    CHECK(std::abs(side - truth) < std::abs(flatter - truth));
    if (x < h) {
      ++edge;
      continue;
    }
    CHECK(side >= light(x - h) - 1e-6);  // within its neighbours
    worst = std::max(worst, std::abs(side - truth) / truth);
    worstMinmod = std::max(worstMinmod, std::abs(flatter - truth) / truth);
    ++inner;
  }
  CHECK(inner == 80);
  CHECK(edge == 10);
  INFO("worst relative error at an inner side: limited central " << worst << ", minmod " << worstMinmod);
  CHECK(worst < 0.25 * worstMinmod);  // measured 0.62 against 4.65 %
}

TEST_CASE(
    "The limited central change is the slope of the parabola through three means, uneven steps too, 0 at a kink "
    "and an extremum, and at most twice the smaller change",
    "[cpu]") {
  // x^2 at x = 1, 2, 4 seen from 2: one-sided changes 3 (a step of 1 down) and 6 (2 up); the
  // parabola's slope at 2 is 4, which an unweighted mean (4.5) misses.
  CHECK(centralLimitedSlope(6, 3, 2, 1) == Approx(4));
  CHECK(centralLimitedSlope(2, 2) == Approx(2));   // a ramp
  CHECK(centralLimitedSlope(1, 0) == 0);           // a kink: flat as minmod
  CHECK(centralLimitedSlope(2, -1, 2, 1) == 0);    // x^2 at -1, 0, 2: its minimum
  CHECK(centralLimitedSlope(10, 1) == Approx(2));  // capped: no profile passes a neighbour
  CHECK(centralLimitedSlope(-10, -1) == Approx(-2));
  // At a chart's edge, x^2 at 1 (the edge's), 2 and 4: changes 3 and 6, the parabola's slope at 1 is 2.
  CHECK(edgeSlope(3, 6, 1, 2) == Approx(2));
  CHECK(edgeSlope(3, -1, 1, 1) == 3);         // an extremum inside: the one-sided change
  CHECK(edgeSlope(1, 10, 1, 1) == 0);         // within 0 and twice the one-sided change
  CHECK(edgeSlope(3, 1, 1, 1) == Approx(4));  // light steepening toward the edge: steeper
}
