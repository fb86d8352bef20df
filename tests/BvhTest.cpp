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

TEST_CASE("BVH nodes bound their triangles and every triangle lies in exactly one leaf", "[bvh]") {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Bvh bvh(scene);
  std::multiset<std::uint32_t> seen;
  // Walk from the root, checking each leaf's triangles against every box above it.
  std::vector<std::pair<std::uint32_t, std::vector<std::uint32_t>>> stack{{0u, {}}};
  while (!stack.empty()) {
    auto [n, above] = stack.back();
    stack.pop_back();
    above.push_back(n);
    const BvhNode& node = bvh.nodes()[n];
    const std::uint32_t first = floatBitsToUint(node.lo.w), count = floatBitsToUint(node.hi.w);
    if (count == 0) {
      REQUIRE(first > n + 1);
      stack.push_back({n + 1, above});
      stack.push_back({first, above});
      continue;
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
  }
  REQUIRE(seen.size() == bvh.triangles().size());
  CHECK(std::set<std::uint32_t>(seen.begin(), seen.end()).size() == seen.size());
  CHECK(bvh.depth() <= int(std::ceil(std::log2(double(bvh.triangles().size())))) + 1);  // median split: balanced
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
