// Instant radiosity (seed 002): the VPL buffers read back in their std430 layout, a closed box
// of emitters reaches its analytic radiosity, forward and deferred shading agree, the clamp's
// reported bias is the light it removes, a seed fixes the image bit for bit, and the CLI.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "src/cli/Solve.h"
#include "src/output/InstantRenderer.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

InstantSettings small(unsigned vpls, unsigned seed = 3) {
  InstantSettings s;
  s.vpls = vpls;
  s.seed = seed;
  s.shadowResolution = 48;
  s.itemSubdivision = 1;
  return s;
}

bool insideConvex(const ScenePolygon& p, glm::dvec3 x, double eps) {
  for (std::size_t i = 0; i < p.vertices.size(); ++i) {
    const glm::dvec3 a = p.vertices[i], b = p.vertices[(i + 1) % p.vertices.size()];
    if (glm::dot(glm::cross(b - a, x - a), p.normal) < -eps * glm::length(b - a)) return false;
  }
  return true;
}

const Scene& cornell() {
  static const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  return scene;
}

}  // namespace

TEST_CASE(
    "VPL buffers read back in the vec4 std430 layout: each VPL lies in its polygon, at its level, at the nearest hit",
    "[gl][instant]") {
  test::backend();
  const Scene& scene = cornell();
  VplTracer tracer(scene, small(500));
  const VplStats stats = tracer.trace();
  const std::vector<GpuVpl> vpls = tracer.readVpls();
  const VplLevels& levels = tracer.levels();
  const double diagonal = tracer.sceneDiagonal();
  double emitted = 0;
  unsigned lit = 0, checkedBounces = 0;
  for (int j = 0; j <= levels.deepest; ++j)
    for (unsigned i = levels.offset[j]; i < levels.offset[j] + levels.count[j]; ++i) {
      const GpuVpl& v = vpls[i];
      if (v.flux == glm::vec4(0.0f)) continue;  // its path ended before level j
      ++lit;
      const std::uint32_t id = floatBitsToUint(v.position.w);
      REQUIRE(id < scene.polygons().size());
      const ScenePolygon& p = scene.polygons()[id];
      CHECK(v.normal.w == float(j));
      CHECK(glm::length(glm::vec3(v.normal) - glm::vec3(p.normal)) < 1e-6f);
      CHECK(std::abs(glm::dot(glm::dvec3(v.position), p.normal) - glm::dot(p.normal, p.vertices[0])) < 1e-5 * diagonal);
      CHECK(insideConvex(p, glm::dvec3(v.position), 1e-5 * diagonal));
      CHECK(v.flux.w == 0.0f);
      if (j == 0) {
        CHECK(scene.materials[p.material].emissive());
        emitted += luminance(glm::dvec3(v.flux));
        continue;
      }
      // The GPU's hit is the nearest along the bounce: the CPU traversal from the path's previous
      // VPL (same path, slot i - offset[j] of level j - 1) meets this VPL's polygon first, there.
      const GpuVpl& from = vpls[levels.offset[j - 1] + (i - levels.offset[j])];
      const glm::vec3 o(from.position), d = glm::vec3(v.position) - o;
      const auto hit = tracer.bvh().intersect(o, glm::normalize(d), floatBitsToUint(from.position.w));
      REQUIRE(hit);
      CHECK(hit->polygon == id);
      CHECK(std::abs(hit->t - glm::length(d)) < 1e-4f * float(diagonal));
      ++checkedBounces;
    }
  // Every path starts with a VPL on an emitter; together they carry the emitted power.
  CHECK(stats.paths == levels.count[0]);
  CHECK(emitted == Approx(stats.emitted).epsilon(1e-4));
  CHECK(emitted == Approx(scene.emittedPower()).epsilon(1e-4));
  CHECK(lit + stats.escapedPaths + stats.behindPaths >=
        levels.count[0]);  // a path ends by a miss or runs out of levels
  CHECK(lit > levels.count[0]);
  CHECK(checkedBounces == lit - levels.count[0]);
}

TEST_CASE("Instant radiosity in a closed box of emitters reaches E (1 + rho + ... + rho^(L+1))", "[gl][instant]") {
  test::backend();
  const double rho = 0.5, E = 1.0;
  const Scene box = test::cube(rho, E);
  const Camera camera = parseCamera("eye=0.5,0.5,0.95 target=0.5,0.5,0 up=0,1,0 fov=30", Camera{}, "test");
  // Independent seeds: their image means give the estimator's standard error (no clamp: unbiased).
  const int seeds = 8;
  std::vector<double> means;
  int deepest = 0;
  for (int k = 0; k < seeds; ++k) {
    InstantSettings s = small(256, 100 + k);
    s.clamp = 0;
    VplTracer tracer(box, s);
    const VplStats stats = tracer.trace();
    CHECK(stats.escapedPaths == 0);  // closed: nothing leaves
    CHECK(stats.behindPaths == 0);
    deepest = tracer.levels().deepest;
    InstantRenderer renderer(box, tracer, s);
    means.push_back(meanLuminance(renderer.render(camera, 24, 24, 1, Shading::Deferred).image));
  }
  double mean = 0, var = 0;
  for (double m : means) mean += m / seeds;
  for (double m : means) var += (m - mean) * (m - mean) / (seeds - 1);
  const double standardError = std::sqrt(var / seeds);
  // Emission, then one bounce per VPL level 0..deepest.
  double expected = 0;
  for (int k = 0; k <= deepest + 1; ++k) expected += E * std::pow(rho, k);
  INFO("mean " << mean << ", expected " << expected << ", standard error " << standardError << ", deepest " << deepest);
  CHECK(standardError < 0.02 * expected);  // the test can see a few-percent bias
  CHECK(std::abs(mean - expected) < 4 * standardError);
}

TEST_CASE("Forward and deferred instant radiosity shading give the same image, interleaved or not", "[gl][instant]") {
  test::backend();
  const Scene& scene = cornell();
  const Camera camera = resolveCamera(scene, std::nullopt);
  // Two batches: the second adds onto the first. Interleave 3: 40 is no multiple of 3 (padded
  // blocks) and 9 subsets do not divide the 256-VPL batch (a subset continues across batches).
  const int interleave = GENERATE(1, 3);
  INFO("interleave " << interleave);
  InstantSettings s = small(300);
  s.interleave = interleave;
  VplTracer tracer(scene, s);
  tracer.trace();
  InstantRenderer renderer(scene, tracer, s);
  const InstantImage f = renderer.render(camera, 40, 40, 1, Shading::Forward);
  const InstantImage d = renderer.render(camera, 40, 40, 1, Shading::Deferred);
  float peak = 0, worst = 0;
  for (std::size_t i = 0; i < f.image.rgb.size(); ++i) {
    peak = std::max(peak, std::abs(d.image.rgb[i]));
    worst = std::max(worst, std::abs(f.image.rgb[i] - d.image.rgb[i]));
  }
  CHECK(peak > 0);
  CHECK(worst <= 1e-5f * peak);
  CHECK(f.clampRemoved == Approx(d.clampRemoved).epsilon(1e-4));
}

TEST_CASE("The clamp's reported bias is the light it removes from the unclamped image", "[gl][instant]") {
  test::backend();
  const Scene& scene = cornell();
  const Camera camera = resolveCamera(scene, std::nullopt);
  InstantSettings clamped = small(128), unclamped = clamped;
  clamped.clamp = 0.1;
  unclamped.clamp = 0;
  VplTracer tracer(scene, clamped);
  tracer.trace();
  const InstantImage a = InstantRenderer(scene, tracer, clamped).render(camera, 32, 32, 1, Shading::Deferred);
  const InstantImage b = InstantRenderer(scene, tracer, unclamped).render(camera, 32, 32, 1, Shading::Deferred);
  CHECK(b.clampRemoved == 0);
  REQUIRE(a.clampRemoved > 1e-3 * a.luminanceSum);  // the clamp bites at this bound
  CHECK(b.luminanceSum - a.luminanceSum == Approx(a.clampRemoved).epsilon(1e-3));
  CHECK(a.clampBias() > 0);
  CHECK(a.clampBias() < 1);
}

TEST_CASE("Instant radiosity: one seed gives bitwise the same image, another seed another", "[gl][instant]") {
  test::backend();
  const Scene& scene = cornell();
  const Camera camera = resolveCamera(scene, std::nullopt);
  auto hash = [&](unsigned seed, int interleave) {
    InstantSettings s = small(64, seed);
    s.interleave = interleave;
    VplTracer tracer(scene, s);
    tracer.trace();
    return imageHash(InstantRenderer(scene, tracer, s).render(camera, 24, 24, 1, Shading::Forward).image);
  };
  const std::uint64_t first = hash(9, 1), interleaved = hash(9, 4);
  CHECK(hash(9, 1) == first);
  CHECK(hash(10, 1) != first);
  CHECK(hash(9, 4) == interleaved);
  CHECK(interleaved != first);
}

TEST_CASE("solve --method instant writes the camera images and a report, and refuses atlas outputs",
          "[heavy][instant][cli]") {
  const std::string png = test::tempPath("instant.png"), exr = test::tempPath("instant.exr"),
                    report = test::tempPath("instant.json");
  const std::string scene = test::sourcePath("scenes/cornell/cornell.obj");
  const test::Run run = test::hemirad("solve " + scene +
                                      " --method instant --vpls 64 --shadow-res 32 --width 24 "
                                      "--height 24 --supersample 1 --quiet --image " +
                                      png + " --out " + exr + " --report " + report);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(std::ifstream(png).good());
  CHECK(std::ifstream(exr).good());
  const nlohmann::json r = nlohmann::json::parse(std::ifstream(report));
  CHECK(r["vpls"] == 64);
  CHECK(r["method"] == "instant");
  CHECK(r["escaped_fraction"].get<double>() >= 0);
  CHECK(r["clamp_bias"].get<double>() >= 0);
  for (const std::string& bad : std::vector<std::string>{"--atlas " + test::tempPath("a.exr"), "--vpls 0", "--shots 4",
                                                         "--shading sideways", "--interleave 0", "--msaa 4"}) {
    const test::Run refused = test::hemirad("solve " + scene + " --method instant --quiet " + bad);
    INFO(bad << ": " << refused.output);
    CHECK(refused.exitCode == 2);
    CHECK(refused.output.rfind("hemirad: error:", 0) == 0);
  }
  for (const std::string flag : {"--vpls 64", "--interleave 2"}) {
    const test::Run notInstant = test::hemirad("solve " + scene + " " + flag + " --quiet");
    CHECK(notInstant.exitCode == 2);
  }
}

TEST_CASE(
    "Interleaved instant radiosity under a smooth light stays within the analytic bound of the exact image, and never "
    "mixes polygons",
    "[gl][instant]") {
  test::backend();
  // A floor of two polygons (rho 0.3 | 0.7, seam at x = 0) lit by a 1 x 1 emitter facing down
  // at height h = 1, direct light only (every VPL on the emitter), no clamp: each VPL's term
  // h^2 / r^4 has |grad log| <= 2 / h, so over the filter's window (pixels at most D apart) a
  // subset's sum changes by at most a factor e^(2D/h), and the interleaved pixel (each subset
  // from one pixel of the window) lies within e^(2D/h) - 1 of the exact one.
  const int interleave = GENERATE(2, 4);
  Scene scene;
  const int dark = test::material(scene, 0.3, 0), light = test::material(scene, 0.7, 0),
            lamp = test::material(scene, 0, 1), o = scene.addObject("floor");
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0);
  scene.addPolygon(test::rectangle({-2, -2, 0}, X, Y, 2, 4), dark, o);
  scene.addPolygon(test::rectangle({0, -2, 0}, X, Y, 2, 4), light, o);
  scene.addPolygon(test::rectangle({-0.5, -0.5, 1}, Y, X, 1, 1), lamp, o);
  const double height = 0.9, fov = 60;  // the camera below the lamp, looking down: floor only
  const Camera camera = parseCamera("eye=0.1,0,0.9 target=0.1,0,0 up=0,1,0 fov=60", Camera{}, "test");
  const int size = 48;
  auto render = [&](int n, std::vector<std::uint32_t>* ids = nullptr) {
    InstantSettings s = small(64);
    s.bounces = 0, s.clamp = 0, s.interleave = n;
    VplTracer tracer(scene, s);
    tracer.trace();
    InstantRenderer renderer(scene, tracer, s);
    Image image = renderer.render(camera, size, size, 1, Shading::Deferred).image;
    if (ids) *ids = renderer.visiblePolygons();
    return image;
  };
  std::vector<std::uint32_t> ids;
  const Image exact = render(1, &ids), interleaved = render(interleave);
  const double pixel = 2 * height * std::tan(glm::radians(fov / 2)) / size;  // on the floor
  const int lo = -(interleave / 2), hi = lo + interleave - 1;                // the filter's window
  const double D = pixel * std::sqrt(2.0) * std::max(-lo, hi), bound = std::exp(2 * D / 1.0) - 1;
  const double rho[2] = {0.3, 0.7};
  double worst = 0, seamError = 0, mixingError = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const std::size_t i = std::size_t(y) * size + x;
      REQUIRE(ids[i] < 2);           // the floor fills the view
      bool whole = true;             // the window lies on the pixel's own polygon
      double window = 0, mixed = 0;  // its pixels, and their reflectance summed
      for (int dy = lo; dy <= hi; ++dy)
        for (int dx = lo; dx <= hi; ++dx) {
          const int u = x + dx, v = y - dy;  // the window is in GL rows (bottom-up), ids top-down
          const bool inside = u >= 0 && v >= 0 && u < size && v < size;
          whole = whole && inside && ids[std::size_t(v) * size + u] == ids[i];
          if (inside) window += 1, mixed += rho[ids[std::size_t(v) * size + u]];
        }
      const double e = luminance(glm::dvec3(exact.rgb[3 * i], exact.rgb[3 * i + 1], exact.rgb[3 * i + 2]));
      const double f =
          luminance(glm::dvec3(interleaved.rgb[3 * i], interleaved.rgb[3 * i + 1], interleaved.rgb[3 * i + 2]));
      const double relative = std::abs(f - e) / e;
      if (whole) {
        worst = std::max(worst, relative);
      } else if (mixed / window != rho[ids[i]]) {  // at the seam: a filter blind to polygons errs by this
        seamError += relative, mixingError += std::abs(mixed / window / rho[ids[i]] - 1);
      }
    }
  INFO("interleave " << interleave << ": worst " << worst << ", bound " << bound << ", seam " << seamError
                     << " against mixing's " << mixingError);
  CHECK(worst > 0);  // interleaving did change the image
  CHECK(worst <= bound + 1e-5);
  // At the seam the filter averages fewer subsets (noisier) but never the other polygon: its
  // error stays under half of what averaging the window's reflectances would make.
  REQUIRE(mixingError > 0);
  CHECK(seamError < 0.5 * mixingError);
}

TEST_CASE("A camera move reuses the shadow maps: the image equals a fresh renderer's", "[gl][instant]") {
  test::backend();
  const Scene& scene = cornell();
  const Camera first = resolveCamera(scene, std::nullopt);
  Camera second = first;
  second.eye += 0.2 * (first.target - first.eye);
  second.target.x += 0.05 * glm::length(first.target - first.eye);
  InstantSettings s = small(64);
  s.interleave = 2;
  VplTracer tracer(scene, s);
  tracer.trace();
  InstantRenderer moving(scene, tracer, s), fresh(scene, tracer, s);
  const std::uint64_t before = imageHash(moving.render(first, 40, 30, 1, Shading::Deferred).image);
  const Image moved = moving.render(second, 32, 24, 1, Shading::Deferred).image;
  CHECK(imageHash(moved) != before);
  CHECK(imageHash(moved) == imageHash(fresh.render(second, 32, 24, 1, Shading::Deferred).image));
}
