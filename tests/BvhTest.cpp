// The BVH the VPL tracer walks (src/solver/Bvh.h): its traversal finds the nearest hit that
// testing every triangle finds, its nodes bound their triangles, and Keller's level plan fills
// the VPL budget exactly.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <set>

#include "src/scene/SceneLoader.h"
#include "src/solver/Bvh.h"
#include "src/solver/VplTracer.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("BVH traversal finds the nearest hit that testing every triangle finds", "[bvh]") {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Bvh bvh(scene);
  const glm::vec3 lo(scene.boundsMin()), hi(scene.boundsMax());
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  int hits = 0;
  for (int k = 0; k < 3000; ++k) {
    const glm::vec3 o = lo + (hi - lo) * glm::vec3(u(rng), u(rng), u(rng));
    const glm::vec3 d = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) - 0.5f);
    const std::uint32_t skip = k % 7 == 0 ? std::uint32_t(k % scene.polygons().size()) : 0xFFFFFFFFu;
    const auto a = bvh.intersect(o, d, skip), b = bvh.intersectAll(o, d, skip);
    REQUIRE(a.has_value() == b.has_value());
    if (!a) continue;
    ++hits;
    CHECK(a->t == b->t);  // the same triangle test on the same floats
    CHECK(a->polygon == b->polygon);
    CHECK(a->polygon != skip);
  }
  CHECK(hits > 1000);  // most rays from inside the box meet a wall
}

namespace {

// Checks node n's subtree (its triangles inside every box above them) and returns the index
// past it: a preorder layout, where a stackless walk goes when it skips n.
std::uint32_t checkSubtree(const Bvh& bvh, std::uint32_t n, std::vector<std::uint32_t> above,
                           std::multiset<std::uint32_t>& seen) {
  above.push_back(n);
  const BvhNode& node = bvh.nodes()[n];
  const std::uint32_t first = floatBitsToUint(node.lo.w), count = floatBitsToUint(node.hi.w);
  if (count == 0) {  // inner: two children, the first right after it, filling [n + 1, first)
    REQUIRE(first > n + 2);
    const std::uint32_t second = checkSubtree(bvh, n + 1, above, seen);
    REQUIRE(checkSubtree(bvh, second, above, seen) == first);
    return first;
  }
  for (std::uint32_t t = first; t < first + count; ++t) {
    seen.insert(t);
    const BvhTriangle& tri = bvh.triangles()[t];
    for (glm::vec3 v :
         {glm::vec3(tri.v0), glm::vec3(tri.v0) + glm::vec3(tri.e1), glm::vec3(tri.v0) + glm::vec3(tri.e2)})
      for (std::uint32_t a : above) {
        CHECK(glm::all(glm::lessThanEqual(glm::vec3(bvh.nodes()[a].lo), v)));
        CHECK(glm::all(glm::greaterThanEqual(glm::vec3(bvh.nodes()[a].hi), v)));
      }
  }
  return n + 1;
}

}  // namespace

TEST_CASE("BVH nodes lie in preorder, bound their triangles, and every triangle lies in exactly one leaf", "[bvh]") {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Bvh bvh(scene);
  std::multiset<std::uint32_t> seen;
  REQUIRE(checkSubtree(bvh, 0, {}, seen) == bvh.nodes().size());  // the root's subtree is every node
  REQUIRE(seen.size() == bvh.triangles().size());
  CHECK(std::set<std::uint32_t>(seen.begin(), seen.end()).size() == seen.size());
  CHECK(bvh.depth() <= Bvh::kMaxDepth);
}

TEST_CASE("A BVH that is a single leaf is walked: its root is the whole walk", "[bvh]") {
  // One quad, two triangles: the root is a leaf (kLeafSize 2), whose index past it is 1.
  Scene scene;
  scene.addPolygon(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 1, 1), test::material(scene, 0.5, 0.0),
                   scene.addObject("quad"));
  const Bvh bvh(scene);
  REQUIRE(bvh.nodes().size() == 1);
  const auto hit = bvh.intersect({0.5f, 1.0f, 0.5f}, {0.0f, -1.0f, 0.0f}, 0xFFFFFFFFu);
  REQUIRE(hit.has_value());
  CHECK(hit->t == Approx(1.0f));
  CHECK_FALSE(bvh.intersect({1.5f, 1.0f, 0.5f}, {0.0f, -1.0f, 0.0f}, 0xFFFFFFFFu).has_value());
}

TEST_CASE("The BVH keeps a room's walls near its root however many small triangles furnish it (surface-area heuristic)",
          "[bvh]") {
  // The Cornell box with a 100 x 100-quad patch (20,000 triangles) on its floor. A median split
  // would put each wall triangle in a leaf about log2(20,038 / 2) = 14 levels down, under boxes as
  // large as the room, which every segment through the patch would then enter.
  Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const int m = test::material(scene, 0.5, 0.0), object = scene.addObject("patch");
  for (int j = 0; j < 100; ++j)
    for (int i = 0; i < 100; ++i)
      scene.addPolygon(test::rectangle({100.0 + i, 0.5, 100.0 + j}, {0, 0, 1}, {1, 0, 0}, 1, 1), m, object);
  const Bvh bvh(scene);
  REQUIRE(bvh.triangles().size() == 20038);
  int deepestWall = 0, deepestPatch = 0;
  std::vector<std::uint32_t> open;  // the ends of the subtrees node n lies in (preorder): its depth
  for (std::uint32_t n = 0; n < bvh.nodes().size(); ++n) {
    while (!open.empty() && open.back() <= n) open.pop_back();
    const int depth = int(open.size());
    const BvhNode& node = bvh.nodes()[n];
    const std::uint32_t first = floatBitsToUint(node.lo.w), count = floatBitsToUint(node.hi.w);
    if (count == 0) {
      open.push_back(first);
      continue;
    }
    for (std::uint32_t t = first; t < first + count; ++t) {
      const bool wall = floatBitsToUint(bvh.triangles()[t].v0.w) < 19;  // the box's 19 polygons come first
      (wall ? deepestWall : deepestPatch) = std::max(wall ? deepestWall : deepestPatch, depth);
    }
  }
  INFO("deepest wall leaf " << deepestWall << ", deepest patch leaf " << deepestPatch << ", depth " << bvh.depth());
  CHECK(deepestWall <= 10);   // measured 8
  CHECK(deepestPatch >= 13);  // the patch itself is as deep as halving 20,000 triangles takes
  CHECK(bvh.depth() <= Bvh::kMaxDepth);
}

TEST_CASE("Keller's level plan fills the VPL budget exactly with geometrically fewer paths per bounce", "[bvh]") {
  for (double rho : {0.0, 0.3, 0.5, 0.75, 1.0})
    for (unsigned vpls : {1u, 7u, 64u, 100u, 512u, 4096u})
      for (int bounces : {0, 3, 8, 15}) {
        const VplLevels l = planLevels(vpls, rho, bounces);
        unsigned sum = 0;
        for (int j = 0; j < kMaxVplLevels; ++j) {
          sum += l.count[j];
          if (j > bounces) CHECK(l.count[j] == 0);
          if (j > 0) CHECK(l.count[j] <= l.count[j - 1]);
          if (j > 0) CHECK(l.offset[j] == l.offset[j - 1] + l.count[j - 1]);
          // n[j] = floor(rho^j N), N = n[0] less the remainder (under one path a level) added to n[0]
          if (j > 0 && j <= bounces) {
            CHECK(l.count[j] <= std::pow(rho, j) * l.count[0] + 1e-9);
            CHECK(l.count[j] >= std::pow(rho, j) * (double(l.count[0]) - (bounces + 1)) - 1.0);
          }
        }
        CHECK(sum == vpls);
        CHECK(l.count[0] >= 1);
      }
}
