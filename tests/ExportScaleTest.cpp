// Issue 29, packing and export at scale: the lightmap's charts pack in near-linear time in their
// count past a thousand, and the .glb keeps a mesh per scene object however its materials mix.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstring>

#include "src/output/ChartPacker.h"
#include "src/output/GltfWriter.h"
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

TEST_CASE("The .glb holds one mesh per scene object, a primitive per material it uses, however the polygons interleave",
          "[cpu][scale]") {
  Scene scene;
  const int grey = test::material(scene, 0.5, 0.0), lamp = test::material(scene, 0.0, 1.0);
  const int a = scene.addObject("table"), b = scene.addObject("lamp"), c = scene.addObject("chair");
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0);
  // (object, material) of each polygon, in scene order; table uses both materials.
  const std::vector<std::pair<int, int>> order{{a, grey}, {b, lamp}, {a, lamp}, {c, grey}, {a, grey}, {c, grey}};
  for (std::size_t k = 0; k < order.size(); ++k)
    scene.addPolygon(test::rectangle({0, 0, double(k)}, X, Y, 1, 1), order[k].second, order[k].first);
  const Atlas atlas = buildAtlas(scene, 0.25);
  const std::vector<glm::vec4> B(atlas.polygonOf.size(), glm::vec4(0.5f));
  const GltfFiles files = encodeGltf({test::tempPath("objects.glb"), ""}, scene, atlas, B, Camera{}, 1.0, 1.0);
  std::uint32_t length = 0;
  std::memcpy(&length, files.glb.data() + 12, 4);
  const nlohmann::json j = nlohmann::json::parse(files.glb.substr(20, length));
  REQUIRE(j["meshes"].size() == 3);
  std::vector<std::string> names;
  std::vector<std::vector<int>> materials;
  std::vector<int> indices;
  for (const auto& mesh : j["meshes"]) {
    names.push_back(mesh["name"]);
    materials.emplace_back();
    for (const auto& p : mesh["primitives"]) {
      materials.back().push_back(p["material"]);
      indices.push_back(j["accessors"][p["indices"].get<int>()]["count"]);
    }
  }
  CHECK(names == std::vector<std::string>{"table", "lamp", "chair"});
  CHECK(materials == std::vector<std::vector<int>>{{grey, lamp}, {lamp}, {grey}});
  CHECK(indices == std::vector<int>{12, 6, 6, 12});  // two triangles a quad: table 2 grey + 1 lamp, lamp 1, chair 2
}
