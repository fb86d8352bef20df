// Issue 29, packing and export at scale: the lightmap's charts pack in near-linear time in their
// count past a thousand, need no gutters (clamped coordinates), and the .glb keeps a mesh per
// scene object however its materials mix.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstring>

#include "src/output/ChartPacker.h"
#include "src/output/GltfWriter.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Files.h"
#include "tests/support/GltfReload.h"
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
  // A quad, 4 x 4 cells, is cut along the lightmap's clamp lines (half a cell in from each side,
  // Lightmap.h) into 3 x 3 pieces, 18 triangles: table 2 grey + 1 lamp, lamp 1, chair 2.
  CHECK(indices == std::vector<int>{108, 54, 54, 108});
}

namespace {
// 4 x 64 small charts, each in its plane z = its index: 0.9 x 0.9 squares, L shapes (three quads),
// right triangles and 0.9 x 0.2 strips of two quads; at texel 0.5 the squares and L's are 2 x 2
// cells, the strips 2 x 1 (each quad crossed by one clamp line: cut in two).
Scene smallShapes() {
  Scene s;
  const int m = test::material(s, 0.5, 0.0), o = s.addObject("shapes");
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0);
  for (int k = 0; k < 256; ++k) {
    const glm::dvec3 at(0, 0, k);
    if (k % 4 == 0) s.addPolygon(test::rectangle(at, X, Y, 0.9, 0.9), m, o);
    if (k % 4 == 1)  // three quads sharing whole edges: one chart
      for (glm::dvec3 corner : {at, at + 0.45 * X, at + 0.45 * Y})
        s.addPolygon(test::rectangle(corner, X, Y, 0.45, 0.45), m, o);
    if (k % 4 == 2) s.addPolygon({at, at + 0.9 * X, at + 0.9 * Y}, m, o);
    if (k % 4 == 3)
      for (glm::dvec3 corner : {at, at + 0.45 * X}) s.addPolygon(test::rectangle(corner, X, Y, 0.45, 0.2), m, o);
  }
  return s;
}
}  // namespace

TEST_CASE(
    "Small charts of squares, L shapes, triangles and strips fill the lightmap without gutters, "
    "never share a texel, and the .glb's TEXCOORD_1 is their clamped coordinate everywhere",
    "[cpu][scale]") {
  const Scene scene = smallShapes();
  const Atlas atlas = buildAtlas(scene, 0.5);
  REQUIRE(atlas.charts.size() == 256);
  std::vector<glm::vec4> B(atlas.polygonOf.size(), glm::vec4(0.0f));
  for (std::size_t t = 0; t < B.size(); ++t) B[t].r = float(t + 1);  // each element its own value
  const GltfFiles files = encodeGltf({test::tempPath("shapes.glb"), ""}, scene, atlas, B, Camera{}, 1.0, 1.0);
  const Lightmap& map = files.map;
  // With 1-texel gutters a 2 x 2 chart takes 4 x 4 texels, at most 4 / 16 of them elements; a
  // triangle laid along its hypotenuse, 3 x 2 cells, 6 / 20; a strip (one cell across: no gutter
  // there) 2 / 4: at most 30 % in all, packed perfectly.
  double cells = 0, padded = 0;
  for (const Chart& c : atlas.charts)
    cells += c.size.x * c.size.y, padded += (c.size.x + 2 * (c.size.x > 1)) * (c.size.y + 2 * (c.size.y > 1));
  INFO(map.width << " x " << map.height << ", " << map.elements << " elements in " << cells << " cells");
  CHECK(map.elements == atlas.elements);
  CHECK(double(map.elements) / padded <= 0.30);
  CHECK(map.texelUse() >= 0.95 * double(map.elements) / cells);  // the cells alone, packed 95 % full or more
  // Texel-exact: every chart's cells on texels of their own, each element's value where its cell lies.
  std::vector<int> owners(map.rgb.size(), 0);
  std::size_t misplaced = 0;
  for (std::size_t k = 0; k < atlas.charts.size(); ++k)
    for (int j = 0; j < atlas.charts[k].size.y; ++j)
      for (int i = 0; i < atlas.charts[k].size.x; ++i) {
        const Chart& c = atlas.charts[k];
        const glm::ivec2 t = map.origins[k] + (map.transposed[k] ? glm::ivec2(j, i) : glm::ivec2(i, j));
        REQUIRE((t.x >= 0 && t.y >= 0 && t.x < map.width && t.y < map.height));
        ++owners[std::size_t(t.y) * map.width + std::size_t(t.x)];
        const std::size_t a = std::size_t(c.origin.y + j) * atlas.width + std::size_t(c.origin.x + i);
        misplaced += atlas.chartAt(a) == k && map.rgb[std::size_t(t.y) * map.width + std::size_t(t.x)].r != B[a].r;
      }
  CHECK(*std::max_element(owners.begin(), owners.end()) == 1);
  CHECK(misplaced == 0);
  // Over every exported triangle, interpolated TEXCOORD_1 is Lightmap::coord, clamped half a cell
  // in from each chart side: the triangles are cut along the clamp lines (else off by up to 0.5).
  const test::ReloadedGltf g = test::reloadGltf(test::writeTempFile("shapes.glb", files.glb));
  double worst = 0;
  for (std::size_t t = 0; t + 2 < g.triangles.size(); t += 3)
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) {
        const double w[3] = {a / 4.0, b / 4.0, 1 - (a + b) / 4.0};
        glm::dvec3 p(0.0);
        glm::dvec2 uv(0.0);
        for (int v = 0; v < 3; ++v) {
          const LightmapVertex& x = g.triangles[t + std::size_t(v)];
          p += w[v] * glm::dvec3(x.position[0], x.position[1], x.position[2]);
          uv += w[v] * glm::dvec2(x.uv[0], x.uv[1]);
        }
        const int polygon = atlas.charts[std::size_t(std::lround(p.z))].polygon;  // chart k lies at z = k
        const glm::dvec2 expected = map.coord(atlas, polygon, atlas.atlasCoord(polygon, p));
        worst = std::max(worst, glm::length(uv * glm::dvec2(map.width, map.height) - expected));
      }
  CHECK(worst < 1e-3);
}

TEST_CASE("The .glb's cut polygons leave no T-junction: no vertex lies inside another triangle's side",
          "[cpu][scale]") {
  // The Cornell room: its walls, floor and ceiling share sides, which their charts' clamp lines cross
  // (its ceiling's own T-junctions, corners of the pieces around the light, are the scene's). The
  // blocks stay out: their faces, made planar on loading, meet a few micrometres apart.
  const Scene cornell = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  Scene scene = sceneLike(cornell);
  for (const ScenePolygon& p : cornell.polygons())
    if (cornell.objects[std::size_t(p.object)].name.find("block") == std::string::npos)
      scene.addPolygon(p.vertices, p.material, p.object);
  const Atlas atlas = buildAtlas(scene, Discretisation{{}, 2000}, 16384);
  const std::vector<glm::vec4> B(atlas.polygonOf.size(), glm::vec4(1.0f));
  const GltfFiles files = encodeGltf({test::tempPath("welded.glb"), ""}, scene, atlas, B, Camera{}, 1.0, 1.0);
  const test::ReloadedGltf g = test::reloadGltf(test::writeTempFile("welded.glb", files.glb));
  std::vector<glm::dvec3> vertices, cuts;  // cuts: the vertices the export made (not the scene's corners)
  for (const LightmapVertex& v : g.triangles) vertices.emplace_back(v.position[0], v.position[1], v.position[2]);
  for (const glm::dvec3& v : vertices) {
    bool corner = false;
    for (const ScenePolygon& p : scene.polygons())
      for (const glm::dvec3& c : p.vertices) corner = corner || glm::length(glm::dvec3(glm::vec3(c)) - v) < 1e-4;
    if (!corner) cuts.push_back(v);
  }
  std::size_t tJunctions = 0, sides = 0;
  for (std::size_t t = 0; t + 2 < vertices.size(); t += 3)
    for (int k = 0; k < 3; ++k, ++sides) {
      const glm::dvec3 a = vertices[t + std::size_t(k)], d = vertices[t + std::size_t(k + 1) % 3] - a;
      for (const glm::dvec3& w : cuts) {
        const double s = glm::dot(w - a, d) / glm::dot(d, d);
        // Inside the side (over 10 um from both ends: float positions of distinct cuts can be that close), on it.
        const double inside = std::min(s, 1 - s) * glm::length(d);
        if (inside > 1e-2 && glm::length(w - (a + s * d)) < 1e-4 && tJunctions < 3)
          FAIL_CHECK(w.x << ", " << w.y << ", " << w.z << " inside side " << a.x << ", " << a.y << ", " << a.z << " + "
                         << d.x << ", " << d.y << ", " << d.z);
        tJunctions += inside > 1e-2 && glm::length(w - (a + s * d)) < 1e-4;  // mm
      }
    }
  INFO(vertices.size() / 3 << " triangles, " << cuts.size() << " vertices at cuts");
  CHECK(sides > 200);
  CHECK(cuts.size() > 100);
  CHECK(tJunctions == 0);
}
