// What the near final gather knows of each element (src/output/GatherSources.h): a border element of
// a chart is a cut cell, so its profile must follow its piece, not its cell.
#include <catch2/catch.hpp>

#include <cmath>

#include "src/output/GatherSources.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Files.h"

using namespace hemirad;

TEST_CASE(
    "The near gather's element profiles follow a linear light across every piece: border cells cut by the "
    "polygon's edge included",
    "[cpu]") {
  // A unit square at texel size 0.3: 4 x 4 cells centred on it, so the outer ones are cut to 0.2
  // and their centroids lie 0.25 from the next ones, not a cell. The light sent grows linearly
  // along x, so each element's change across its piece is exact: 2 b hu.x over its own light.
  // Before, a border element's change was taken per cell step from a centroid 0.25 away (17 %
  // short) and spread over the whole cell.
  const std::string path =
      test::writeScene("linear_light", "mtllib m.mtl\nusemtl w\nv 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n",
                       "newmtl w\nKd 0.5 0.5 0.5\n");
  const Scene scene = loadScene(path);
  const Atlas atlas = buildAtlas(scene, 0.3);
  const ShooterTree tree = buildShooterTree(atlas, atlas.shooterBlocks(4), 4);
  const double a = 1, b = 2;
  std::vector<glm::vec4> sent(atlas.positionArea.size(), glm::vec4(0.0f));
  for (std::size_t t = 0; t < sent.size(); ++t)
    if (atlas.positionArea[t].w > 0) sent[t] = glm::vec4(glm::vec3(float(a + b * atlas.positionArea[t].x)), 0.0f);
  const std::vector<glm::vec4> sources = gatherSources(atlas, tree.nodes, sent);
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
