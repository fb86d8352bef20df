// Issue 31's unbiased reference: `hemirad reference` reaches the furnace's exact B = 2 within its
// own standard errors, the plates' and perpendicular squares' exact point form factors, and the
// converged radiosity solution in surface interiors; a seed fixes its bytes; `hemirad compare`
// prints known errors for images with known errors, per region; bad input is one error line.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "cpu/ExactFormFactor.h"
#include "src/output/ImageFile.h"
#include "src/reference/BatchStatistics.h"
#include "src/reference/ErrorTable.h"
#include "src/reference/PathTracer.h"
#include "src/reference/PixelRegions.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Bvh.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

std::string analyticScene(const std::string& name) { return test::sourcePath("scenes/analytic/" + name); }

ReferenceEstimate referenceOf(const Scene& scene, const Camera& camera, int size, unsigned spp, unsigned seed = 7,
                              unsigned bounces = kReferenceBounceCap) {
  test::backend();
  ReferenceSettings s;
  s.width = s.height = size, s.samples = spp, s.batches = 16, s.seed = seed, s.bounces = bounces;
  BatchStatistics statistics(size, size, spp / s.batches);
  PathTracer(scene).render(camera, s, [&](const std::vector<glm::vec4>& sums) { statistics.add(sums); });
  return statistics.estimate();
}

double pixelLum(const Image& image, std::size_t p) {
  return hemirad::luminance(glm::dvec3(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]));
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int countOf(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t p = 0; (p = text.find(what, p)) != std::string::npos; p += what.size()) ++n;
  return n;
}

// The reference against B = rho F(x -> emitter) at each receiver pixel centre in a surface
// interior (exact: the emitter is black, so light makes one bounce); returns the largest
// |difference| in standard errors and sets the mean relative difference.
double exactReceiverCheck(const std::string& name, const std::optional<std::string>& cameraText, double& meanRelative) {
  const Scene scene = loadScene(analyticScene(name));
  const Camera camera = resolveCamera(scene, cameraText);
  const int size = 48;
  const ReferenceEstimate e = referenceOf(scene, camera, size, 256);
  const PixelRegions regions = pixelRegions(scene, camera, size, size);
  const Bvh bvh(scene);
  const ScenePolygon& emitter = scene.polygons()[0];
  const cpu::Polygon shape(emitter.vertices.begin(), emitter.vertices.end());
  const Camera::PixelRays rays = camera.pixelRays(size, size);
  double worst = 0, sum = 0;
  int n = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const std::size_t p = std::size_t(y) * size + x;
      if (regions.polygon[p] != 1 || regions.edgeDistance[p] < PixelRegions::kEdgeReach) continue;
      const glm::dvec3 d = glm::normalize(rays.corner + (x + 0.5) * rays.dx + (size - 1 - y + 0.5) * rays.dy);
      const glm::dvec3 hit = camera.eye + double(bvh.intersect(glm::vec3(camera.eye), glm::vec3(d), kNoPolygon)->t) * d;
      const ScenePolygon& r = scene.polygons()[1];
      const double exact = 0.5 * cpu::pointToPolygon(hit, r.normal, shape, emitter.normal);
      worst = std::max(worst, std::abs(pixelLum(e.mean, p) - exact) / e.luminanceError[p]);
      sum += (pixelLum(e.mean, p) - exact) / exact, ++n;
    }
  REQUIRE(n > 100);
  meanRelative = sum / n;
  return worst;
}

}  // namespace

TEST_CASE(
    "The reference sees the furnace's exact B = 2 at every pixel within 6 standard errors and on average within 0.5 %",
    "[gl][reference]") {
  const Scene scene = loadScene(analyticScene("furnace.obj"));
  const ReferenceEstimate e = referenceOf(scene, resolveCamera(scene, std::nullopt), 64, 64);
  double worst = 0;
  for (std::size_t p = 0; p < e.luminanceError.size(); ++p) {
    REQUIRE(e.luminanceError[p] > 0);
    worst = std::max(worst, std::abs(pixelLum(e.mean, p) - 2.0) / e.luminanceError[p]);
  }
  INFO("mean " << e.meanLuminance << ", mean standard error " << e.meanStandardError);
  CHECK(worst < 6.0);  // Student's t with 15 degrees of freedom: P(|t| > 6) ~ 2e-5 a pixel
  CHECK(std::abs(e.meanLuminance - 2.0) < 0.01);
}

// --bounces N: in the closed furnace (E 1, rho 1/2 everywhere) light reflected at most N times
// sums to B_N = 1 + 1/2 + ... + 1/2^N exactly; 1 is the direct light per-pixel direct light computes.
TEST_CASE("With --bounces N the reference sees the furnace's exact partial sum 2 - 2^-N of its reflections",
          "[gl][reference]") {
  const Scene scene = loadScene(analyticScene("furnace.obj"));
  const Camera camera = resolveCamera(scene, std::nullopt);
  for (unsigned n : {0u, 1u, 2u}) {
    const ReferenceEstimate e = referenceOf(scene, camera, 32, 64, 7, n);
    const double exact = 2.0 - std::ldexp(1.0, -int(n));
    double worst = 0;
    for (std::size_t p = 0; p < e.luminanceError.size(); ++p)
      worst = std::max(worst, std::abs(pixelLum(e.mean, p) - exact) / std::max(e.luminanceError[p], 1e-7));
    INFO("--bounces " << n << ": mean " << e.meanLuminance << " (exact " << exact << "), worst " << worst
                      << " standard errors");
    CHECK(worst < 6.0);
    CHECK(std::abs(e.meanLuminance - exact) < 0.005 * exact);
  }
}

TEST_CASE(
    "The reference matches the plates' and the perpendicular squares' exact point form factors in surface interiors",
    "[gl][reference]") {
  // The plates' own camera sees them edge on: this one looks at the receiver from between them.
  const std::pair<std::string, std::optional<std::string>> views[] = {
      {"parallel_squares.obj", "eye=0.5,0.5,0.05 target=0.5,0.5,1 up=0,1,0 fov=70"}, {"perpendicular_squares.obj", {}}};
  for (const auto& [name, view] : views) {
    double meanRelative = 0;
    const double worst = exactReceiverCheck(name, view, meanRelative);
    INFO(name << ": worst " << worst << " standard errors, mean relative difference " << meanRelative);
    CHECK(worst < 6.0);
    CHECK(std::abs(meanRelative) < 0.005);
  }
}

TEST_CASE(
    "The reference and a converged radiosity solve of the perpendicular squares agree in surface interiors within the "
    "solver's error and the reference's noise",
    "[gl][reference][heavy]") {  // converged values: the reference runs under ASan on the furnace (9 s there)
  const Scene scene = loadScene(analyticScene("perpendicular_squares.obj"));
  const Camera camera = resolveCamera(scene, std::nullopt);
  ProgressiveSettings settings;
  settings.stop = {0, 0.999};
  Discretisation elements;
  elements.elements = 2500;  // a quarter of the default: the solve in a few seconds
  const test::Solved solved = test::solve(scene, chooseTexelSize(scene, elements), settings, &camera);  // 128^2
  const ReferenceEstimate e = referenceOf(scene, camera, 128, 256);
  const PixelRegions regions = pixelRegions(scene, camera, 128, 128);
  const std::vector<ErrorRow> rows = errorTable(scene, regions, solved.view, e.mean, e.standardError);
  INFO(markdown(rows));
  const ErrorRow& interior = rows.front();
  REQUIRE(interior.pixels > 2000);
  // The solver's interior error (hemicube form factors, bilinear B between element centres) is
  // under 0.5 %; the reference's noise averages down over the interior's pixels (3 standard
  // errors of their mean) or, per pixel, stays about its own size (E|e| = 0.8 sigma for a normal e).
  CHECK(std::abs(interior.bias) < 0.005 + 3 * interior.noise / std::sqrt(double(interior.pixels)));
  CHECK(interior.meanAbsolute < 0.005 + interior.noise);
}

TEST_CASE(
    "A reference's bytes are fixed by its seed: the same seed writes identical files, another seed different ones",
    "[gl][reference][cli][heavy]") {
  auto run = [](unsigned seed, const std::string& name) {
    const std::string out = test::tempPath(name);
    const test::Run r = test::hemirad("reference " + analyticScene("furnace.obj") +
                                      " --spp 32 --batches 4 --width 24 --height 24 --seed " + std::to_string(seed) +
                                      " --out " + out + ".exr --stderr " + out + "_se.exr");
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return fileBytes(out + ".exr") + fileBytes(out + "_se.exr");
  };
  const std::string a = run(1, "seed1a"), b = run(1, "seed1b"), c = run(2, "seed2");
  CHECK(a == b);
  CHECK(a != c);
}

TEST_CASE(
    "compare prints the known error of an image scaled by 1.01 in every region, and a bias put on the corner band "
    "lands there alone",
    "[gl][reference][cli]") {
  const std::string scene = analyticScene("perpendicular_squares.obj");
  const Scene loaded = loadScene(scene);
  const int size = 64;
  const PixelRegions regions = pixelRegions(loaded, resolveCamera(loaded, std::nullopt), size, size);
  Image b{size, size, std::vector<float>(3 * size * size)}, a = b, cornered = b;
  for (std::size_t p = 0; p < b.rgb.size() / 3; ++p)
    for (int c = 0; c < 3; ++c) {
      b.rgb[3 * p + c] = 0.25f + 0.001f * float(p % 97) + 0.1f * float(c);
      a.rgb[3 * p + c] = b.rgb[3 * p + c] * 1.01f;
      cornered.rgb[3 * p + c] = b.rgb[3 * p + c] * (regions.creaseDistance[p] == 1 ? 0.98f : 1.0f);
    }
  const std::string pa = test::tempPath("scaled.exr"), pb = test::tempPath("truth.exr"),
                    pc = test::tempPath("cornered.exr"), map = test::tempPath("map.png");
  writeExr(pa, a), writeExr(pb, b), writeExr(pc, cornered);
  const test::Run r = test::hemirad("compare " + pa + " " + pb + " --scene " + scene + " --error-map " + map);
  INFO(r.output);
  REQUIRE(r.exitCode == 0);
  CHECK(countOf(r.output, "| 1.000 % | 1.000 % | +1.000 % |") == 8);  // 3 bands, interior, edge, 2 objects, image
  CHECK(std::ifstream(map).good());
  const std::vector<ErrorRow> rows = errorTable(loaded, regions, cornered, b, Image{});
  REQUIRE(rows[2].region == "corner band (1 px)");
  REQUIRE(rows[2].pixels > 10);
  CHECK(rows[2].bias == Approx(-0.02).margin(1e-6));
  CHECK(rows[0].bias == 0.0);  // the interior
  CHECK(rows[3].bias == 0.0);  // 2 px from the crease
}

TEST_CASE(
    "The region beside a light is exactly the ceiling pixels 1-3 px from a light hung under it whose square misses the "
    "light's image, not a nearer parallel panel",
    "[reference]") {
  // Looking straight up at a ceiling (y = 1) with a light hung `gap` under it and a parallel panel
  // at y = 0.5 beside it in the image; all face down. A pixel is 1/32 in units of the image plane
  // at distance 1 (fov 90, 64 px): the light's sides lie on pixel boundaries (x = +-8 px, z = -4
  // px) but its far side 0.1 px into the next row (z = 8.1 px), whose 16 squares it overlaps.
  const glm::dvec3 X(1, 0, 0), Z(0, 0, 1);
  const double gap = 0.001, h = 1 - gap;  // the contact distance is 1e-3 of the diagonal (14.1): 0.014
  const double x0 = -0.25, x1 = 0.25, z0 = -0.125, z1 = 8.1 / 32;  // the light on the image plane
  Scene s;
  const int white = test::material(s, 0.5, 0), lamp = test::material(s, 0.5, 1);
  s.addPolygon(test::rectangle({-5, 1, -5}, X, Z, 10, 10), white, s.addObject("ceiling"));
  s.addPolygon(test::rectangle({x0 * h, h, z0 * h}, X, Z, (x1 - x0) * h, (z1 - z0) * h), lamp, s.addObject("light"));
  s.addPolygon(test::rectangle({0.14, 0.5, -0.25}, X, Z, 0.86, 0.75), white, s.addObject("panel"));
  const Camera camera = parseCamera("eye=0,0,0 target=0,1,0 up=0,0,1 fov=90", Camera{}, "test");
  const int size = 64;
  const PixelRegions regions = pixelRegions(s, camera, size, size);
  // Window point w on the image plane (x, z); what each pixel centre sees first: 0 ceiling, 1 light, 2 panel.
  const Camera::PixelRays rays = camera.pixelRays(size, size);
  auto onPlane = [&](double wx, double wy) {
    const glm::dvec3 d = rays.corner + wx * rays.dx + wy * rays.dy;
    return glm::dvec2(d.x, d.z) / d.y;
  };
  std::vector<int> seen(size * size);
  std::vector<bool> overlapsLight(size * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec2 c = onPlane(x + 0.5, size - 1 - y + 0.5), panel = c * 0.5;  // the panel is at y = 0.5
      seen[y * size + x] = panel.x >= 0.14 && panel.y >= -0.25 && panel.y <= 0.5 ? 2
                           : c.x >= x0 && c.x <= x1 && c.y >= z0 && c.y <= z1    ? 1
                                                                                 : 0;
      const glm::dvec2 a = onPlane(x, size - 1 - y), b = onPlane(x + 1, size - y);
      const glm::dvec2 lo = glm::min(a, b) + 1e-9, hi = glm::max(a, b) - 1e-9;
      overlapsLight[y * size + x] = lo.x < x1 && hi.x > x0 && lo.y < z1 && hi.y > z0;
    }
  std::vector<int> lightPixels;
  for (int p = 0; p < size * size; ++p)
    if (seen[p] == 1) lightPixels.push_back(p);
  int besidePixels = 0, overlapping = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const int p = y * size + x;
      REQUIRE(int(regions.polygon[p]) == seen[p]);
      int k = PixelRegions::kFar;  // Chebyshev distance to the nearest light pixel
      for (int q : lightPixels) k = std::min(k, std::max(std::abs(q % size - x), std::abs(q / size - y)));
      overlapping += seen[p] == 0 && overlapsLight[p];
      const bool beside = seen[p] == 0 && k <= 3 && !overlapsLight[p];
      INFO("pixel " << x << ", " << y << " sees " << seen[p] << ", " << k << " px from the light");
      CHECK((regions.lightDistance[p] <= PixelRegions::kLightReach) == beside);
      if (!beside) continue;
      CHECK(regions.lightDistance[p] == k);
      ++besidePixels;
    }
  // The light covers 16 x 12 pixel centres; around it 22 x 18 less the light, the panel's 2 x 18
  // and the 16 the light's far side overlaps.
  CHECK(lightPixels.size() == 16 * 12);
  CHECK(overlapping == 16);
  CHECK(besidePixels == 22 * 18 - 16 * 12 - 2 * 18 - 16);
}

TEST_CASE("Bad reference and compare input is one error line and a nonzero exit before any work",
          "[gl][reference][cli][bad-input]") {
  const std::string furnace = analyticScene("furnace.obj"), out = test::tempPath("bad.exr");
  auto oneError = [](const std::string& args, const std::string& message) {
    const test::Run r = test::hemirad(args);
    INFO("hemirad " << args << "\n" << r.output);
    CHECK(r.exitCode == 2);
    CHECK(countOf(r.output, "hemirad: error:") == 1);
    CHECK_THAT(r.output, Contains(message));
  };
  oneError("reference " + furnace + " --spp 100 --batches 16 --out " + out, "not a multiple of --batches");
  oneError("reference " + furnace + " --out " + out + " --stderr " + out, "give each output its own");
  oneError("reference " + furnace + " --bounces 4097 --out " + out, "--bounces");
  oneError("compare " + test::tempPath("missing.exr") + " " + out + " --scene " + furnace, "missing.exr");
  const std::string small = test::tempPath("small.exr"), large = test::tempPath("large.exr");
  writeExr(small, Image{4, 4, std::vector<float>(48, 1.0f)});
  writeExr(large, Image{8, 8, std::vector<float>(192, 1.0f)});
  oneError("compare " + small + " " + large + " --scene " + furnace, "is 8 x 8 pixels, the images compared 4 x 4");
  oneError("compare " + analyticScene("analytic.mtl") + " " + large + " --scene " + furnace,
           "compare reads linear EXR or PFM images");
}

TEST_CASE(
    "The lean hemirad-bench writes hemirad reference's image as PFM: the same pixels, rows bottom up as PFM keeps "
    "them",
    "[gl][reference][cli][heavy]") {
  const std::string out = test::tempPath("lean"), flags = " --spp 32 --batches 4 --width 24 --height 16 --seed 3";
  const std::string scene = analyticScene("perpendicular_squares.obj");
  const test::Run full = test::hemirad("reference " + scene + flags + " --out " + out + ".exr");
  const test::Run lean =
      test::shell("\"$(dirname \"$HEMIRAD\")/hemirad-bench\" reference " + scene + flags + " --out " + out + ".pfm");
  INFO(full.output << lean.output);
  REQUIRE(full.exitCode == 0);
  REQUIRE(lean.exitCode == 0);
  const Image exr = readImage(out + ".exr");
  std::istringstream pfm(fileBytes(out + ".pfm"));
  std::string magic;
  int width = 0, height = 0;
  double scale = 0;
  pfm >> magic >> width >> height >> scale;
  pfm.get();  // the one whitespace byte before the floats
  REQUIRE(magic == "PF");
  REQUIRE((width == 24 && height == 16 && scale == -1.0));  // -1: little-endian
  std::vector<float> rows(exr.rgb.size());
  pfm.read(reinterpret_cast<char*>(rows.data()), std::streamsize(rows.size() * sizeof(float)));
  REQUIRE(pfm.gcount() == std::streamsize(rows.size() * sizeof(float)));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 3 * width; ++x)
      REQUIRE(rows[std::size_t((height - 1 - y) * 3 * width + x)] == exr.rgb[std::size_t(y * 3 * width + x)]);
  CHECK(readImage(out + ".pfm").rgb == exr.rgb);  // and compare reads it back as the EXR
}
