// Issue 31's per-pixel direct light (`solve --direct per-pixel`, docs/design.md#per-pixel-direct):
// a receiver under a one-sided square lamp shows rho E F(x -> lamp), the exact point form factor,
// at every pixel; behind a hard occluder the umbra is black, the lit part exact and the penumbra
// the exact form factor to the lamp's visible part within the visibility grid's step; on the
// Cornell box the split into per-pixel direct and atlas indirect light neither loses nor adds
// light against the atlas image; it and the near final gather write the same bytes each run; a bad
// value is one error line.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "cpu/ExactFormFactor.h"
#include "src/output/DirectLight.h"
#include "src/output/ImageFile.h"
#include "src/output/Renderer.h"
#include "src/reference/ErrorTable.h"
#include "src/reference/PixelRegions.h"
#include "src/scene/SceneLoader.h"
#include "src/scene/SmoothNormals.h"
#include "src/solver/Bvh.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

constexpr int kDirectSize = 48;

// `solve SCENE --direct MODE` at kDirectSize^2, one sample a pixel (its centre, where the
// CPU's ray goes), read back.
Image directSolve(const std::string& scene, const std::string& camera, const std::string& more = "",
                  const std::string& mode = "per-pixel") {
  const std::string out = test::tempPath("direct.exr");
  const test::Run run =
      test::hemirad("solve " + scene + " --camera '" + camera + "' --width " + std::to_string(kDirectSize) +
                    " --height " + std::to_string(kDirectSize) +
                    " --supersample 1 --msaa 1 --ambient off --quiet --direct " + mode + " --out " + out + " " + more);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  return readImage(out);
}

// Where the ray through pixel (x, y)'s centre (rows top-down) meets the scene.
glm::dvec3 pixelHit(const Camera& camera, const Bvh& bvh, int x, int y) {
  const Camera::PixelRays rays = camera.pixelRays(kDirectSize, kDirectSize);
  const glm::dvec3 d = glm::normalize(rays.corner + (x + 0.5) * rays.dx + (kDirectSize - 1 - y + 0.5) * rays.dy);
  return camera.eye + double(bvh.intersect(glm::vec3(camera.eye), glm::vec3(d), kNoPolygon)->t) * d;
}

// A square lamp (E 1, black) at z = 0 facing +z, [0.4, 0.6]^2; a receiver (rho 0.5) at z = 1
// facing it; a black occluder at z = 0.5 over x < 0.5, both sides. Nothing reflects twice, so
// the receiver's B is its direct light: 0.5 F(x -> the part of the lamp with x_lamp > 1 - x).
std::string occluderScene() {
  const std::string dir = test::tempPath("occluder");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/occluder.mtl") << "newmtl lamp\nKd 0 0 0\nKe 1 1 1\nnewmtl grey\nKd 0.5 0.5 0.5\n"
                                          "newmtl black\nKd 0 0 0\n";
  std::ofstream(dir + "/occluder.obj")
      << "mtllib occluder.mtl\no lamp\nusemtl lamp\n"
         "v 0.4 0.4 0\nv 0.6 0.4 0\nv 0.6 0.6 0\nv 0.4 0.6 0\nf 1 2 3 4\n"
         "o receiver\nusemtl grey\nv -0.5 -0.5 1\nv -0.5 1.5 1\nv 1.5 1.5 1\nv 1.5 -0.5 1\nf 5 6 7 8\n"
         "o occluder\nusemtl black\nv -1 -1 0.5\nv 0.5 -1 0.5\nv 0.5 2 0.5\nv -1 2 0.5\nf 9 10 11 12\n";
  return dir + "/occluder.obj";
}

cpu::Polygon lampPart(double x0) {  // the lamp's part with x >= x0, counter-clockwise around +z
  return {{x0, 0.4, 0}, {0.6, 0.4, 0}, {0.6, 0.6, 0}, {x0, 0.6, 0}};
}

}  // namespace

TEST_CASE(
    "Per-pixel direct light under a square lamp is rho E times the exact point form factor at every receiver pixel",
    "[gl][direct]") {
  const std::string path = test::sourcePath("scenes/analytic/parallel_squares.obj");
  const std::string view = "eye=0.5,0.5,0.05 target=0.5,0.5,1 up=0,1,0 fov=70";  // between the plates
  const Image image = directSolve(path, view, "--elements 400 --converge 0.999");
  const Scene scene = loadScene(path);
  const Camera camera = resolveCamera(scene, view);
  const PixelRegions regions = pixelRegions(scene, camera, kDirectSize, kDirectSize);
  const Bvh bvh(scene);
  const ScenePolygon& lamp = scene.polygons()[0];
  const cpu::Polygon shape(lamp.vertices.begin(), lamp.vertices.end());
  double worst = 0;
  int n = 0;
  for (int y = 0; y < kDirectSize; ++y)
    for (int x = 0; x < kDirectSize; ++x) {
      const std::size_t p = std::size_t(y) * kDirectSize + x;
      if (regions.polygon[p] != 1 || regions.edgeDistance[p] < 1) continue;
      const double exact =
          0.5 * cpu::pointToPolygon(pixelHit(camera, bvh, x, y), scene.polygons()[1].normal, shape, lamp.normal);
      worst = std::max(worst, std::abs(image.rgb[3 * p + 1] - exact) / exact), ++n;
    }
  REQUIRE(n > 1000);
  CHECK(worst < 1e-4);
}

TEST_CASE(
    "Per-pixel direct light behind a hard occluder: umbra black, lit pixels exact, the penumbra the exact form factor "
    "to the lamp's visible part within the grid's step, and sharper than the atlas's",
    "[gl][direct][heavy]") {
  const std::string path = occluderScene();
  const std::string view = "eye=0.5,0.5,0.6 target=0.5,0.5,1 up=0,1,0 fov=90";  // between occluder and receiver
  const std::string elements = "--elements 100 --converge 0.999";               // elements ~0.3 wide, the penumbra 0.2
  const Image image = directSolve(path, view, elements);
  const Image atlas = directSolve(path, view, elements, "atlas");
  const Scene scene = loadScene(path);
  const Camera camera = resolveCamera(scene, view);
  const Bvh bvh(scene);
  const glm::dvec3 down(0, 0, -1), up(0, 0, 1);
  int umbra = 0, lit = 0, penumbra = 0, band = 0;
  double worstLit = 0, worstPenumbra = 0, brightestUmbra = 0, bandError = 0, atlasBandError = 0;
  for (int y = 0; y < kDirectSize; ++y)
    for (int x = 0; x < kDirectSize; ++x) {
      const glm::dvec3 hit = pixelHit(camera, bvh, x, y);
      const double value = image.rgb[3 * (std::size_t(y) * kDirectSize + x) + 1];
      const double full = 0.5 * cpu::pointToPolygon(hit, down, lampPart(0.4), up);
      if (hit.x > 0.25 && hit.x < 0.75) {  // the shadow's edge, +-0.15 around the penumbra's 0.2
        const double exact = 0.5 * cpu::pointToPolygon(hit, down, lampPart(std::clamp(1 - hit.x, 0.4, 0.6)), up);
        bandError += std::abs(value - exact) / full, ++band;
        atlasBandError += std::abs(atlas.rgb[3 * (std::size_t(y) * kDirectSize + x) + 1] - exact) / full;
      }
      if (hit.x < 0.39) {
        brightestUmbra = std::max(brightestUmbra, value), ++umbra;
      } else if (hit.x > 0.61) {
        worstLit = std::max(worstLit, std::abs(value - full) / full), ++lit;
      } else if (hit.x > 0.41 && hit.x < 0.59) {
        const double exact = 0.5 * cpu::pointToPolygon(hit, down, lampPart(1 - hit.x), up);
        worstPenumbra = std::max(worstPenumbra, std::abs(value - exact) / full), ++penumbra;
      }
    }
  REQUIRE(umbra > 200);
  REQUIRE(lit > 200);
  REQUIRE(penumbra > 100);
  CHECK(brightestUmbra == 0);
  CHECK(worstLit < 1e-4);
  // The 8 x 8 grid's midpoint rule: within half a column's light, 1/16 of the lamp's (measured 4.2 %).
  CHECK(worstPenumbra < 0.5 / kDirectGrid);
  // Across the shadow's edge the elements blur the penumbra; the pixels do not (measured: mean
  // error 1.1 % of the lamp's light per pixel, 33 % with --direct atlas; 2.6 % at 400 elements).
  INFO("mean error across the edge: per-pixel " << bandError / band << ", atlas " << atlasBandError / band);
  CHECK(bandError / band < 0.02);
  CHECK(bandError < atlasBandError / 4);
}

TEST_CASE(
    "On the Cornell box the per-pixel image and the atlas image agree in surface interiors: the direct/indirect split "
    "neither loses nor adds light",
    "[gl][direct][heavy]") {
  const std::string cornell = test::sourcePath("scenes/cornell/cornell.obj");
  const std::string common =
      "solve " + cornell + " --elements 1000 --converge 0.99 --width 64 --height 64 --ambient off --quiet";
  const std::string atlas = test::tempPath("cornell_atlas.exr"), perPixel = test::tempPath("cornell_pp.exr");
  const std::string report = test::tempPath("cornell_pp.json");
  REQUIRE(test::hemirad(common + " --out " + atlas).exitCode == 0);
  const test::Run run = test::hemirad(common + " --direct per-pixel --out " + perPixel + " --report " + report);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  const Scene scene = loadScene(cornell);
  const PixelRegions regions = pixelRegions(scene, resolveCamera(scene, std::nullopt), 64, 64);
  const std::vector<ErrorRow> rows = errorTable(scene, regions, readImage(perPixel), readImage(atlas), Image{});
  INFO(markdown(rows));
  const ErrorRow& interior = rows.front();
  REQUIRE(interior.pixels > 1000);
  CHECK(interior.meanAbsolute < 0.02);
  CHECK(std::abs(interior.bias) < 0.01);
  std::ifstream in(report);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK_THAT(text, Contains("\"direct\": \"per-pixel\"") && Contains("\"direct_ms\""));
  CHECK_THAT(text, Contains("\"direct_shares\": 1"));  // one lamp: its walks fit one draw on llvmpipe too
}

TEST_CASE("Per-pixel direct light and the near final gather are deterministic: the same solve writes the same bytes",
          "[gl][direct][heavy]") {
  const std::string squares = test::sourcePath("scenes/analytic/parallel_squares.obj");
  const std::string cornell = test::sourcePath("scenes/cornell/cornell.obj");
  for (const std::string& run : {"solve " + squares + " --elements 400 --direct per-pixel",
                                 "solve " + cornell + " --elements 300 --direct per-pixel --final-gather near"}) {
    const std::string a = test::tempPath("direct_a.exr"), b = test::tempPath("direct_b.exr");
    const std::string common = run + " --width 32 --height 32 --quiet --out ";
    REQUIRE(test::hemirad(common + a).exitCode == 0);
    REQUIRE(test::hemirad(common + b).exitCode == 0);
    std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
    const std::string bytesA((std::istreambuf_iterator<char>(fa)), {}),
        bytesB((std::istreambuf_iterator<char>(fb)), {});
    INFO(run);
    CHECK(!bytesA.empty());
    CHECK(bytesA == bytesB);
  }
}

TEST_CASE(
    "Bad --direct or --final-gather input is one error line and exit code 2: an unknown mode, a method without it, a "
    "walkthrough, the gather with atlas direct light, an exact image plan it cannot give",
    "[gl][direct][cli][bad-input]") {
  const std::string cornell = test::sourcePath("scenes/cornell/cornell.obj");
  const std::string out = " --out " + test::tempPath("bad_direct.exr");
  const std::pair<std::string, std::string> cases[] = {
      {"--direct perpixel", "--direct: perpixel not in {auto,atlas,per-pixel}"},
      {"--method stochastic --direct per-pixel", "--direct is for --method progressive, not stochastic"},
      {"--direct per-pixel --camera-path " + test::sourcePath("scenes/cornell/cornell.path") + " --frames " +
           test::tempPath("frames"),
       "--direct per-pixel renders one solve's --out and --image, not --camera-path frames"},
      {"--final-gather near --camera-path " + test::sourcePath("scenes/cornell/cornell.path") + " --frames " +
           test::tempPath("frames"),
       "--final-gather near renders one solve's --out and --image, not --camera-path frames"},
      {"--direct per-pixel --final-gather far", "--final-gather: far not in {auto,off,near}"},
      {"--direct atlas --final-gather near",
       "--final-gather near adds to per-pixel direct light: it cannot take --direct atlas"},
      {"--image-plan best", "--image-plan: best not in {auto,quick,exact}"},
      {"--image-plan exact --method stochastic --shots 4",
       "--image-plan exact takes per-pixel direct light and the near final gather, progressive refinement's, not "
       "stochastic's"},
      {"--image-plan exact --camera-path " + test::sourcePath("scenes/cornell/cornell.path") + " --frames " +
           test::tempPath("frames"),
       "--image-plan exact renders one solve's --out and --image, not --camera-path frames"}};
  for (const auto& [flags, message] : cases) {
    const test::Run run = test::hemirad("solve " + cornell + " " + flags + out);
    INFO(flags << ": " << run.output);
    CHECK(run.exitCode == 2);
    CHECK_THAT(run.output, Contains(message));
    CHECK(std::count(run.output.begin(), run.output.end(), '\n') == 1);
  }
}

// Under --direct per-pixel images take only the indirect light from the elements, so adaptive
// rounds split where the indirect light is steep (src/cli/AdaptiveRounds.cpp). The occluder's
// shadow is in the direct light alone (nothing reflects twice): it splits leaves with the direct
// light in the atlas, none without.
TEST_CASE("Under per-pixel direct light adaptive rounds split on the indirect light: a direct shadow splits no leaf",
          "[gl][direct][adaptive]") {
  const std::string common = "solve " + occluderScene() +
                             " --camera 'eye=0.5,0.5,0.05 target=0.5,0.5,1 up=0,1,0 fov=70' --width 16 --height 16"
                             " --supersample 1 --quiet --subdivide adaptive --elements 4000 --direct ";
  const auto splitsOfRound0 = [&](const std::string& mode) {
    const test::Run run = test::hemirad(common + mode + " --out " + test::tempPath("split.exr"));
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    const std::size_t at = run.output.find("adaptive round 0:");
    REQUIRE(at != std::string::npos);
    const std::string line = run.output.substr(at, run.output.find('\n', at) - at);
    const std::size_t end = line.rfind(" leaves split"), start = line.rfind(' ', end - 1) + 1;
    return std::stoi(line.substr(start, end - start));
  };
  CHECK(splitsOfRound0("atlas") > 0);
  CHECK(splitsOfRound0("per-pixel") == 0);
}

TEST_CASE(
    "Per-pixel direct light on a curved chart takes the smooth normal: a 24-sided cylinder's pixels are rho E "
    "times the exact point form factor at the interpolated normal, not the facet's",
    "[gl][direct]") {
  test::backend();
  Scene scene;
  const int lampMaterial = test::material(scene, 0.0, 1.0), grey = test::material(scene, 0.5, 0.0);
  // A square lamp at x = 1.5 facing -x, beside a cylinder (radius 0.4) standing at the origin.
  REQUIRE(scene.addPolygon({{1.5, 0.2, -0.4}, {1.5, 0.2, 0.4}, {1.5, 1.0, 0.4}, {1.5, 1.0, -0.4}}, lampMaterial,
                           scene.addObject("lamp")));
  test::addCylinder(scene, {0.0, 0.0, 0.0}, 0.4, 1.2, 24, grey, scene.addObject("cylinder"));
  const Atlas atlas = buildAtlas(scene, 0.02, 16384, 0, kDefaultChartAngle);
  REQUIRE(!atlas.vertexNormals.empty());
  SolverState state(scene, atlas);
  const DirectLight light(scene, state.farDistance);
  Renderer renderer(state);
  renderer.show(std::vector<glm::vec4>(atlas.polygonOf.size(), glm::vec4(0.0f)));  // no indirect light: convex
  renderer.usePerPixelDirect(light);
  const int size = 96;
  const Camera camera{{1.3, 0.6, 1.3}, {0.0, 0.6, 0.0}, {0, 1, 0}, 40.0};
  const Image image = renderer.render(camera, size, size, 1);

  const Bvh bvh(scene);
  const ScenePolygon& lamp = scene.polygons()[0];
  const cpu::Polygon shape(lamp.vertices.begin(), lamp.vertices.end());
  const Camera::PixelRays rays = camera.pixelRays(size, size);
  double worst = 0, worstFlat = 0;
  int n = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 d = glm::normalize(rays.corner + (x + 0.5) * rays.dx + (size - 1 - y + 0.5) * rays.dy);
      const auto hit = bvh.intersect(glm::vec3(camera.eye), glm::vec3(d), kNoPolygon);
      if (!hit || hit->polygon == 0) continue;
      const ScenePolygon& facet = scene.polygons()[hit->polygon];
      const glm::dvec3 p = camera.eye + double(hit->t) * d;
      const glm::dvec3 smooth = smoothNormalAt(facet, atlas.vertexNormals[hit->polygon], p);
      // The lamp wholly above both the facet's and the smooth tangent plane: F needs no clipping, nothing occludes.
      bool above = true;
      for (const glm::dvec3& v : lamp.vertices)
        above = above && glm::dot(v - p, smooth) > 0.01 && glm::dot(v - p, facet.normal) > 0.01;
      if (!above) continue;
      const double exact = 0.5 * cpu::pointToPolygon(p, smooth, shape, lamp.normal);
      const double flat = 0.5 * cpu::pointToPolygon(p, facet.normal, shape, lamp.normal);
      const double got = image.rgb[(std::size_t(y) * size + x) * 3 + 1];
      worst = std::max(worst, std::abs(got - exact) / exact),
      worstFlat = std::max(worstFlat, std::abs(flat - exact) / exact);
      ++n;
    }
  INFO(n << " pixels; worst relative error " << worst << ", the facet normal's " << worstFlat);
  REQUIRE(n > 300);
  CHECK(worstFlat > 0.01);  // the facets' normals are that far off: the test can tell them apart
  CHECK(worst < 1e-3);
}
