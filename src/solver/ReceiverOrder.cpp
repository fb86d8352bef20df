#include "src/solver/ReceiverOrder.h"

#include <algorithm>
#include <bit>
#include <utility>

#include <glm/common.hpp>

#include "src/scene/Atlas.h"

namespace hemirad {

namespace {

// The low 10 bits of v, spread to every third bit.
std::uint32_t spread(std::uint32_t v) {
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  return (v | (v << 2)) & 0x09249249u;
}

std::uint32_t mortonCode(glm::dvec3 p, glm::dvec3 lo, glm::dvec3 scale) {
  const glm::uvec3 q(glm::clamp((p - lo) * scale, glm::dvec3(0.0), glm::dvec3(1023.0)));
  return spread(q.x) | spread(q.y) << 1 | spread(q.z) << 2;
}

// i's lowest `bits` bits in reverse order.
std::uint32_t reversed(std::uint32_t i, int bits) {
  std::uint32_t r = 0;
  for (int b = 0; b < bits; ++b) r |= ((i >> b) & 1u) << (bits - 1 - b);
  return r;
}

std::uint32_t packed(int x, int y) { return std::uint32_t(x) | std::uint32_t(y) << 16; }

}  // namespace

std::vector<std::uint32_t> receiverOrder(const Atlas& atlas, glm::dvec3 lo, glm::dvec3 hi, unsigned group) {
  const glm::dvec3 scale = 1023.0 / glm::max(hi - lo, glm::dvec3(1e-30));
  std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed;  // (Morton code, texel)
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      const std::size_t t = std::size_t(y) * std::size_t(atlas.width) + std::size_t(x);
      if (atlas.polygonOf[t] != kNoPolygon)
        keyed.emplace_back(mortonCode(glm::dvec3(atlas.positionArea[t]), lo, scale), packed(x, y));
    }
  std::sort(keyed.begin(), keyed.end());
  // The full workgroups by their bit-reversed index (distinct: every index has `bits` bits), then the short one.
  const std::uint32_t full = std::uint32_t(keyed.size() / group);
  const int bits = std::bit_width(full);
  std::vector<std::uint32_t> groups(full);
  for (std::uint32_t g = 0; g < full; ++g) groups[g] = g;
  std::sort(groups.begin(), groups.end(),
            [&](std::uint32_t a, std::uint32_t b) { return reversed(a, bits) < reversed(b, bits); });
  std::vector<std::uint32_t> order;
  order.reserve(keyed.size());
  for (std::uint32_t g : groups)
    for (std::size_t k = std::size_t(g) * group; k < std::size_t(g + 1) * group; ++k) order.push_back(keyed[k].second);
  for (std::size_t k = std::size_t(full) * group; k < keyed.size(); ++k) order.push_back(keyed[k].second);
  return order;
}

}  // namespace hemirad
