// The gather's visiting order (src/solver/ReceiverOrder.h): every receiver once, workgroups of
// neighbouring points, and either half of a dispatch's workgroups spread over the whole scene
// (what keeps both of llvmpipe's threads busy); against the atlas's 8 x 8 tiles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ReceiverOrder.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

constexpr unsigned kOrderGroup = 64;

glm::dvec3 centreOf(const Atlas& atlas, std::uint32_t packed) {
  return glm::dvec3(atlas.positionArea[std::size_t(packed >> 16) * std::size_t(atlas.width) + (packed & 0xFFFFu)]);
}

// Every receiver texel in the atlas's 8 x 8 tiles, the gather's order before the curve.
std::vector<std::uint32_t> atlasTiles(const Atlas& atlas) {
  std::vector<std::uint32_t> order;
  for (int ty = 0; ty < atlas.height; ty += 8)
    for (int tx = 0; tx < atlas.width; tx += 8)
      for (int y = ty; y < std::min(ty + 8, atlas.height); ++y)
        for (int x = tx; x < std::min(tx + 8, atlas.width); ++x)
          if (atlas.polygonOf[std::size_t(y) * std::size_t(atlas.width) + std::size_t(x)] != kNoPolygon)
            order.push_back(std::uint32_t(x) | std::uint32_t(y) << 16);
  return order;
}

// The median diagonal of the workgroups' bounding boxes.
double medianGroupExtent(const Atlas& atlas, const std::vector<std::uint32_t>& order) {
  std::vector<double> extents;
  for (std::size_t g = 0; g + kOrderGroup <= order.size(); g += kOrderGroup) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (std::size_t k = g; k < g + kOrderGroup; ++k)
      lo = glm::min(lo, centreOf(atlas, order[k])), hi = glm::max(hi, centreOf(atlas, order[k]));
    extents.push_back(glm::length(hi - lo));
  }
  std::nth_element(extents.begin(), extents.begin() + extents.size() / 2, extents.end());
  return extents[extents.size() / 2];
}

// The share of the receivers in [begin, end) of `order` in each octant of the scene's bounds.
std::array<double, 8> octantShares(const Atlas& atlas, const std::vector<std::uint32_t>& order, std::size_t begin,
                                   std::size_t end, glm::dvec3 mid) {
  std::array<double, 8> share{};
  for (std::size_t k = begin; k < end; ++k) {
    const glm::dvec3 p = centreOf(atlas, order[k]);
    share[std::size_t(p.x > mid.x) | std::size_t(p.y > mid.y) << 1 | std::size_t(p.z > mid.z) << 2] +=
        1.0 / double(end - begin);
  }
  return share;
}

}  // namespace

TEST_CASE(
    "The gather visits each receiver once, in workgroups of nearby points, each half of them "
    "spread over the scene",
    "[cpu]") {
  // 64 rooms: charts of a wall each, which the atlas packs side by side from rooms far apart.
  const Scene s = loadScene(test::sourcePath("scenes/building/building_64.obj"));
  const Atlas atlas = buildAtlas(s, texelSizeForElements(s, 10000));
  const std::vector<std::uint32_t> order = receiverOrder(atlas, s.boundsMin(), s.boundsMax(), kOrderGroup),
                                   tiles = atlasTiles(atlas);
  std::vector<std::uint32_t> sorted = order, expected = tiles;
  std::sort(sorted.begin(), sorted.end());
  std::sort(expected.begin(), expected.end());
  REQUIRE(sorted == expected);

  const double extent = medianGroupExtent(atlas, order), atlasExtent = medianGroupExtent(atlas, tiles);
  INFO("median workgroup diagonal: " << extent << " along the curve, " << atlasExtent << " in atlas tiles");
  CHECK(extent < 0.5 * atlasExtent);

  const std::size_t half = order.size() / kOrderGroup / 2 * kOrderGroup;
  const glm::dvec3 mid = 0.5 * (s.boundsMin() + s.boundsMax());
  const std::array<double, 8> first = octantShares(atlas, order, 0, half, mid),
                              second = octantShares(atlas, order, half, order.size(), mid);
  for (std::size_t o = 0; o < 8; ++o) {
    INFO("octant " << o << ": " << first[o] << " of the first half's receivers, " << second[o] << " of the second's");
    CHECK(std::abs(first[o] - second[o]) < 0.02);
  }
}
