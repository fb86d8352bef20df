// Issue 29, packing and export at scale: the lightmap's charts pack in near-linear time in their
// count past a thousand, and the .glb keeps a mesh per scene object however its materials mix.
#include <catch2/catch.hpp>

#include "src/output/ChartPacker.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("2,000 random charts, past the one-by-one turning, pack without overlap into at least 95 % of the image",
          "[cpu][scale]") {
  std::vector<glm::ivec2> sizes;
  std::uint32_t state = 12345;
  auto next = [&state](int most) { return int((state = state * 1664525u + 1013904223u) >> 16) % most; };
  std::size_t padded = 0;
  for (int k = 0; k < 2000; ++k) {
    // Mostly small charts, some long ones, with 2-texel gutters.
    const glm::ivec2 s(1 + next(next(8) == 0 ? 40 : 6) + 4, 1 + next(6) + 4);
    sizes.push_back(s);
    padded += std::size_t(s.x) * std::size_t(s.y);
  }
  const ChartLayout layout = packCharts(sizes, 2, 8.0);
  INFO(layout.width << " x " << layout.height);
  CHECK(std::max(layout.width, layout.height) <= 8 * std::min(layout.width, layout.height));
  // Occupancy of the untrimmed image: every padded chart on texels of its own.
  const int w = layout.width + 4, h = layout.height + 4;
  std::vector<std::uint8_t> owner(std::size_t(w) * std::size_t(h), 0);
  std::size_t overlaps = 0, outside = 0;
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    const glm::ivec2 s = layout.transposed[i] ? glm::ivec2(sizes[i].y, sizes[i].x) : sizes[i];
    for (int y = 0; y < s.y; ++y)
      for (int x = 0; x < s.x; ++x) {
        const glm::ivec2 t = layout.corners[i] + 2 + glm::ivec2(x, y);
        if (t.x < 0 || t.y < 0 || t.x >= w || t.y >= h) {
          ++outside;
          continue;
        }
        overlaps += owner[std::size_t(t.y) * std::size_t(w) + std::size_t(t.x)]++ != 0;
      }
  }
  CHECK(outside == 0);
  CHECK(overlaps == 0);
  CHECK(double(padded) / (double(w) * h) >= 0.95);
}
