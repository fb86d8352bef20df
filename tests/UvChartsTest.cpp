// UV-mapped charts (issue 29, src/scene/ChartMapping.h, src/scene/InputUv.h): with --uv input the
// input's lightmap UV islands are the charts, laid as the input lays them under one scale; their
// elements cover the surface exactly, lie on it, and a closed box of them solves to E / (1 - rho).
#include <tiny_gltf.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <fstream>

#include "src/base/Error.h"
#include "src/scene/Atlas.h"
#include "src/scene/InputUv.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/SolverState.h"
#include "src/solver/StochasticSolver.h"
#include "src/solver/TexelParts.h"
#include "tests/bad_input/BadInput.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

// Face f's UVs: its own square axes (a similarity of the face) scaled by 0.1 + 0.02 f, in cell f
// of a 3 x 2 grid; face 2 mirrored, as some lightmappers lay an island.
Poly2 faceUv(const Poly3& face, int f) {
  const glm::dvec3 e1 = glm::normalize(face[1] - face[0]), e2 = glm::normalize(face.back() - face[0]);
  const double scale = 0.1 + 0.02 * f;
  const glm::dvec2 cell(0.05 + (f % 3) / 3.0, 0.05 + (f / 3) / 2.0);
  Poly2 out;
  for (const glm::dvec3& v : face) {
    glm::dvec2 q(glm::dot(v - face[0], e1), glm::dot(v - face[0], e2));
    if (f == 2) q.x = 1 - q.x;
    out.push_back(cell + scale * q);
  }
  return out;
}

// test::cube (faces inward, unit squares) with a UV island per face.
Scene uvCube(double rho, double E) {
  Scene s = test::cube(rho, E);
  s.path = "uv cube";
  for (std::size_t f = 0; f < s.polygons().size(); ++f)
    s.lightmapUv.push_back(faceUv(s.polygons()[f].vertices, int(f)));
  return s;
}

double twiceArea(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

double elementArea(const Atlas& a) {
  double sum = 0;
  for (std::size_t t = 0; t < a.positionArea.size(); ++t)
    if (a.polygonOf[t] != kNoPolygon) sum += a.positionArea[t].w;
  return sum;
}

// Appends `values` to buffer 0 as a view and an accessor; returns the accessor.
template <class T>
int addAccessor(tinygltf::Model& m, const std::vector<T>& values, int componentType, int type, std::size_t count) {
  std::vector<unsigned char>& data = m.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0, view.byteOffset = data.size(), view.byteLength = values.size() * sizeof(T);
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  data.insert(data.end(), bytes, bytes + view.byteLength);
  m.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = int(m.bufferViews.size()) - 1, a.componentType = componentType, a.type = type, a.count = count;
  m.accessors.push_back(a);
  return int(m.accessors.size()) - 1;
}

// `s` as a glTF of one mesh, a fanned primitive per polygon with TEXCOORD_1 its lightmap UVs
// (none when `uvs` is false); every material rho 0.5, E 1.
std::string writeGltf(const Scene& s, const std::string& name, bool uvs) {
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.buffers.emplace_back();
  m.meshes.emplace_back();
  tinygltf::Material wall;
  wall.pbrMetallicRoughness.baseColorFactor = {0.5, 0.5, 0.5, 1};
  wall.emissiveFactor = {1, 1, 1};
  m.materials.push_back(wall);
  for (std::size_t p = 0; p < s.polygons().size(); ++p) {
    std::vector<float> xyz, uv;
    std::vector<std::uint32_t> fan;
    const Poly3& v = s.polygons()[p].vertices;
    for (std::size_t k = 0; k < v.size(); ++k)
      xyz.insert(xyz.end(), {float(v[k].x), float(v[k].y), float(v[k].z)}),
          uv.insert(uv.end(), {float(s.lightmapUv[p][k].x), float(s.lightmapUv[p][k].y)});
    for (std::uint32_t k = 1; k + 1 < v.size(); ++k) fan.insert(fan.end(), {0, k, k + 1});
    tinygltf::Primitive prim;
    prim.material = 0;
    prim.attributes["POSITION"] = addAccessor(m, xyz, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, v.size());
    if (uvs)
      prim.attributes["TEXCOORD_1"] = addAccessor(m, uv, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, v.size());
    prim.indices = addAccessor(m, fan, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, fan.size());
    m.meshes[0].primitives.push_back(prim);
  }
  tinygltf::Node node;
  node.mesh = 0;
  m.nodes.push_back(node);
  m.scenes.emplace_back().nodes = {0};
  m.defaultScene = 0;
  const std::string path = test::tempPath(name + ".gltf");
  REQUIRE(tinygltf::TinyGLTF().WriteGltfSceneToFile(&m, path, true, true, true, false));
  return path;
}

}  // namespace

TEST_CASE(
    "glTF TEXCOORD_1 islands are charts under --uv input: element areas sum to the surface and atlas coordinates are "
    "the input UVs under one scale",
    "[cpu]") {
  const Scene written = uvCube(0.5, 1.0);
  const Scene s = loadScene(writeGltf(written, "uv-cube", true));
  REQUIRE(s.polygons().size() == 6);
  REQUIRE(s.lightmapUv.size() == 6);
  for (std::size_t p = 0; p < 6; ++p)
    for (std::size_t k = 0; k < 4; ++k) CHECK(glm::length(s.lightmapUv[p][k] - written.lightmapUv[p][k]) < 1e-6);
  const std::size_t wanted = 300;
  const Atlas a = buildAtlas(s, texelSizeForElements(s, wanted, kDefaultChartAngle, UvSource::Input), 16384, 0,
                             kDefaultChartAngle, UvSource::Input);
  CHECK(a.charts.size() == 6);
  CHECK(elementArea(a) == Approx(s.totalArea()).epsilon(1e-6));  // areas are floats
  CHECK(double(a.elements) == Approx(double(wanted)).epsilon(0.1));
  // Texels per UV unit: every triangle's atlas edges are its UV edges times one factor, turned
  // but not mirrored (the mirrored island is mirrored back).
  double factor = 0;
  for (std::size_t p = 0; p < 6; ++p) {
    const Poly3& v = s.polygons()[p].vertices;
    const Poly2& uv = s.lightmapUv[p];
    for (std::size_t k = 1; k + 1 < v.size(); ++k) {
      const glm::dvec2 A = a.atlasCoord(int(p), v[0]), B = a.atlasCoord(int(p), v[k]),
                       C = a.atlasCoord(int(p), v[k + 1]);
      const double ratio = twiceArea(A, B, C) / twiceArea(uv[0], uv[k], uv[k + 1]);
      if (factor == 0) factor = std::sqrt(std::abs(ratio));
      INFO("polygon " << p << " triangle " << k);
      CHECK(ratio == Approx((p == 2 ? -1 : 1) * factor * factor).epsilon(1e-6));
      CHECK(glm::length(B - A) == Approx(factor * glm::length(uv[k] - uv[0])).epsilon(1e-6));
      CHECK(glm::length(C - B) == Approx(factor * glm::length(uv[k + 1] - uv[k])).epsilon(1e-6));
    }
  }
}

TEST_CASE("A closed box of UV-chart walls (islands of several scales, one mirrored) converges to E / (1 - rho)",
          "[gl]") {
  const double rho = 0.5, E = 1;
  const Scene s = uvCube(rho, E);
  test::backend();
  const Atlas atlas = buildAtlas(s, texelSizeForElements(s, 150, kDefaultChartAngle, UvSource::Input), 16384, 0,
                                 kDefaultChartAngle, UvSource::Input);
  SolverState state(s, atlas);
  ProgressiveSettings settings;
  settings.stop.targetConvergence = 0.999;  // what is left unshot lowers B by < 0.1 %
  ProgressiveSolver solver(state, settings);
  SolveStatus status;
  while (!status.done) status = solver.advance(64);
  const double mean = objectRadiosity(s, atlas, state.readRadiosity()).front().mean.x, exact = E / (1 - rho);
  INFO(atlas.elements << " elements, " << status.shots << " shots: mean B " << mean << ", E / (1 - rho) " << exact);
  CHECK(mean == Approx(exact).epsilon(0.003));
}

TEST_CASE(
    "Stochastic iteration on UV-chart walls samples their texels' pieces: the closed box's mean B is E / (1 - rho)",
    "[gl]") {
  // Each sampled texel shoots as its ready-cut pieces (shaders/texel_shape.glsl); the disc it falls
  // back to would lose about 2 % in a closed box (docs/design.md#form-factor), over the 1 % allowed.
  const Scene s = uvCube(0.5, 1.0);
  test::backend();
  const Atlas atlas = buildAtlas(s, 0.25, 16384, 0, kDefaultChartAngle, UvSource::Input);
  SolverState state(s, atlas);
  StochasticSettings settings;
  settings.seed = 7, settings.shooters = 8, settings.itemResolution = 128, settings.itemSubdivision = 0;
  settings.projection = Projection::Hemicube;
  settings.timings = gl::TimerMode::Off;
  settings.stop.maxShots = 512;
  StochasticSolver solver(state, settings);
  for (SolveStatus status; !status.done;) status = solver.advance(64);
  const double mean = objectRadiosity(s, atlas, state.readRadiosity()).front().mean.x;
  INFO(atlas.elements << " elements, 512 iterations of 8 shooters: mean B " << mean);
  CHECK(mean == Approx(2.0).epsilon(0.01));
}

TEST_CASE(
    "A cylinder unrolled in UV is one chart: element areas sum to its area and every texel piece lies on its facets",
    "[cpu]") {
  Scene s;
  const int grey = test::material(s, 0.5, 0.0), obj = s.addObject("cylinder");
  const int slices = 24;
  const double chord = 2 * std::sin(M_PI / slices);
  test::addCylinder(s, glm::dvec3(0.0), 1, 1, slices, grey, obj);
  for (int i = 0; i < slices; ++i) {  // vertices (i + 1, 0), (i, 0), (i, 1), (i + 1, 1): u runs against i
    const double u0 = (slices - i - 1) * chord, u1 = (slices - i) * chord;
    s.lightmapUv.push_back({{u0, 0}, {u1, 0}, {u1, 1}, {u0, 1}});
  }
  const Atlas a = buildAtlas(s, texelSizeForElements(s, 400, kDefaultChartAngle, UvSource::Input), 16384, 0,
                             kDefaultChartAngle, UvSource::Input);
  REQUIRE(a.charts.size() == 1);
  CHECK(!a.charts[0].planar);
  CHECK(elementArea(a) == Approx(s.totalArea()).epsilon(1e-6));  // areas are floats
  CHECK(double(a.elements) == Approx(400.0).epsilon(0.1));
  const double step = 2 * M_PI / slices;
  double pieces = 0;  // in double
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (const Poly3& piece : a.elementShape(s, x, y)) {
        pieces += area(piece);
        glm::dvec3 c(0.0);
        for (auto& v : piece) c += v / double(piece.size());
        // The facet under the piece's centroid (facet i spans angles [i, i + 1) steps), by angle.
        const double phi = std::fmod(std::atan2(c.z, c.x) + 2 * M_PI, 2 * M_PI);
        const ScenePolygon& facet = s.polygons()[std::size_t(std::min(int(phi / step), slices - 1))];
        INFO("texel " << x << ", " << y);
        for (auto& v : piece) CHECK(std::abs(glm::dot(v - facet.vertices[0], facet.normal)) < 1e-9);
        CHECK(c.y >= -1e-12);
        CHECK(c.y <= 1 + 1e-12);
      }
  CHECK(pieces == Approx(s.totalArea()).epsilon(1e-12));
}

TEST_CASE(
    "Stochastic iteration's texel parts of a UV chart are its texels' pieces, under a header whose prism clip keeps "
    "them "
    "whole",
    "[cpu]") {
  const Scene s = uvCube(0.5, 1.0);
  const Atlas a = buildAtlas(s, 0.15, 16384, 0, kDefaultChartAngle, UvSource::Input);
  const TexelParts parts = texelParts(a);
  for (std::size_t c = 0; c < a.charts.size(); ++c) {  // zero axes and texel size: clip bounds 0, distances 0
    CHECK(parts.charts[4 * c] == glm::vec4(0.0f));
    CHECK(parts.charts[4 * c + 1] == glm::vec4(0.0f));
    CHECK(parts.charts[4 * c + 2] == glm::vec4(0.0f));
  }
  for (std::size_t t = 0; t < a.polygonOf.size(); ++t) {
    double sum = 0;
    for (std::uint32_t e = parts.index[t]; e < parts.index[t + 1]; e += 2) {
      Poly3 piece;
      for (std::uint32_t v = 0; v < parts.index[e + 1]; ++v)
        piece.push_back(glm::dvec3(parts.charts[parts.index[e] + v]));
      sum += area(piece);
    }
    INFO("texel " << t);
    CHECK(sum == Approx(a.positionArea[t].w).epsilon(1e-5));
  }
}

TEST_CASE("Lightmap UVs that overlap, fold or collapse are refused with one error naming the polygon", "[cpu]") {
  SECTION("a hexagon's six triangles spread over 540 degrees of UV: one island over itself") {
    Scene s;
    const int grey = test::material(s, 0.5, 0.0), obj = s.addObject("hexagon");
    auto rim = [](double degrees, double r) {
      return r * glm::dvec2(std::cos(degrees * M_PI / 180), std::sin(degrees * M_PI / 180));
    };
    for (int i = 0; i < 6; ++i) {
      const glm::dvec2 a = rim(60 * i, 1), b = rim(60 * (i + 1), 1);
      s.addPolygon({glm::dvec3(0.0), glm::dvec3(a, 0), glm::dvec3(b, 0)}, grey, obj);
      s.lightmapUv.push_back({glm::dvec2(0.5), 0.5 + rim(90 * i, 0.3), 0.5 + rim(90 * (i + 1), 0.3)});
    }
    REQUIRE(inputUvCharts(s).size() == 1);
    CHECK_THROWS_WITH(buildAtlas(s, 0.05, 16384, 0, kDefaultChartAngle, UvSource::Input),
                      Contains("UV triangles of polygon 0's chart overlap"));
  }
  SECTION("a degenerate UV triangle") {
    Scene s = uvCube(0.5, 1.0);
    for (glm::dvec2& q : s.lightmapUv[3]) q.y = 0.5;
    CHECK_THROWS_WITH(inputUvCharts(s), Contains("polygon 3 has a degenerate or folded UV triangle"));
  }
}

TEST_CASE("Bad input: --uv input on a scene without lightmap UVs is one error naming the file", "[cli][bad-input]") {
  const std::string gltf = writeGltf(uvCube(0.5, 1.0), "no-uv", false);
  test::bad_input::expectRefused(
      "uv-input", "solve " + gltf + " --uv input --shots 2 --quiet",
      {"no-uv.gltf: --uv input needs lightmap UVs (glTF TEXCOORD_1, OBJ vt) on every face; 6 of 6 "
       "polygons have none"});
}

TEST_CASE("Bad input: adaptive subdivision with input UVs is one error before the scene is read", "[cli][bad-input]") {
  test::bad_input::expectRefused(
      "uv-adaptive",
      "solve " + test::sourcePath("scenes/cornell/cornell.gltf") + " --uv input --subdivide adaptive --shots 2 --quiet",
      {"--subdivide adaptive splits projection charts; it cannot take --uv input's charts"});
}

TEST_CASE(
    "An OBJ's vt are its lightmap UVs under --uv input: two quads sharing UVs along their edge are one island, a "
    "third with its own UVs another, and a face without vt is refused naming its polygon",
    "[cpu]") {
  const std::string mtl = test::tempPath("vt.mtl"), obj = test::tempPath("vt.obj");
  std::ofstream(mtl) << "newmtl grey\nKd 0.5 0.5 0.5\n";
  // A 2 x 1 floor of two quads (UVs 0..2 x 0..1, shared along x = 1) and a 1 x 1 wall at x = 3
  // (UVs 5..6, its own island), every UV at twice the position's scale.
  const std::string body =
      "mtllib vt.mtl\nusemtl grey\nv 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 0 -1\nv 1 0 -1\nv 2 0 -1\n"
      "v 3 0 0\nv 3 1 0\nv 3 1 -1\nv 3 0 -1\n"
      "vt 0 0\nvt 2 0\nvt 4 0\nvt 0 2\nvt 2 2\nvt 4 2\nvt 10 0\nvt 12 0\nvt 12 2\nvt 10 2\n"
      "f 1/1 2/2 5/5 4/4\nf 2/2 3/3 6/6 5/5\nf 7/7 8/8 9/9 10/10\n";
  std::ofstream(obj) << body;
  const Scene s = loadScene(obj);
  REQUIRE(s.lightmapUv.size() == 3);
  CHECK(s.lightmapUv[1] == Poly2{{2, 0}, {4, 0}, {4, 2}, {2, 2}});
  const std::vector<ChartGroup> charts = inputUvCharts(s);
  REQUIRE(charts.size() == 2);
  CHECK(charts[0].polygons == std::vector<int>{0, 1});
  CHECK(charts[1].polygons == std::vector<int>{2});
  double surface = 0, mapped = 0;  // one scale for the scene: chart area is surface area
  for (const ChartGroup& g : charts)
    for (std::size_t k = 0; k < g.parts.size(); ++k) surface += area(g.parts[k]), mapped += signedArea(g.uv[k]);
  CHECK(mapped == Approx(surface).epsilon(1e-12));
  std::ofstream(obj) << body << "v 0 1 0\nf 1 2 11\n";  // a triangle without vt
  CHECK_THROWS_WITH(inputUvCharts(loadScene(obj)),
                    Catch::Contains("--uv input needs lightmap UVs (glTF TEXCOORD_1, OBJ vt) on every face; 1 of 4 "
                                    "polygons have none (the first: polygon 3)"));
}
