// --msaa (src/output/CameraTarget.h): coverage at N samples a cell, shading once a cell and surface.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gl/Limits.h"
#include "src/output/CameraTarget.h"
#include "src/output/Renderer.h"
#include "src/output/Supersample.h"
#include "src/reference/PixelRegions.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/CornellView.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

double pixelLuminance(const Image& img, std::size_t p) {
  return luminance(glm::dvec3(img.rgb[3 * p], img.rgb[3 * p + 1], img.rgb[3 * p + 2]));
}

}  // namespace

TEST_CASE(
    "MSAA finds a per-pixel render's edges closer to a 16 x 16 grid's than the plain 2 x 2 grid, and leaves pixels "
    "that one triangle covers as they were",
    "[gl][camera][direct][heavy]") {  // repeated renders: MSAA runs under ASan in the refusal test (8 s there)
  test::backend();
  const test::CornellView v;
  const Camera& camera = v.camera;
  Renderer renderer(v.state);
  renderer.show(v.sent);
  renderer.usePerPixelDirect(v.light);
  const int size = 40;
  const Image fine = renderer.render(camera, size, size, 16);
  const Image plain = renderer.render(camera, size, size, 2);
  renderer.setMultisample(4);  // llvmpipe's most
  const Image msaa = renderer.render(camera, size, size, 2);

  const PixelRegions regions = pixelRegions(v.scene, camera, size, size);
  double plainEdge = 0, msaaEdge = 0;
  int edges = 0, interiors = 0, same = 0;
  double worstInterior = 0;
  for (std::size_t p = 0; p < regions.edgeDistance.size(); ++p) {
    const double truth = pixelLuminance(fine, p);
    if (regions.edgeDistance[p] <= 1) {
      plainEdge += std::abs(pixelLuminance(plain, p) - truth) / truth;
      msaaEdge += std::abs(pixelLuminance(msaa, p) - truth) / truth;
      ++edges;
    } else if (regions.edgeDistance[p] >= PixelRegions::kEdgeReach) {
      const double a = pixelLuminance(msaa, p), b = pixelLuminance(plain, p);
      worstInterior = std::max(worstInterior, std::abs(a - b) / b);
      same += std::abs(a - b) <= 1e-5 * b;
      ++interiors;
    }
  }
  plainEdge /= edges, msaaEdge /= edges;
  INFO("edge pixels " << edges << ": mean |e| against 16 x 16, 2 x 2 " << plainEdge << ", 2 x 2 with 4 samples "
                      << msaaEdge << "; interiors " << interiors << ", the same " << same << ", worst "
                      << worstInterior);
  REQUIRE(edges > 200);
  CHECK(msaaEdge < 0.6 * plainEdge);
  // Interiors: the same fragment in every sample (the resolve's pairwise mean gives it exactly;
  // llvmpipe interpolates in its multisample path with other roundings, ~1e-6), unless a
  // triangle's diagonal crosses the pixel (two fragments, each shaded at its centroid).
  // Measured: 165 of 188 within 1e-5, the worst 0.92 %; edges 13.1 -> 4.3 %.
  CHECK(same > 0.8 * interiors);
  CHECK(worstInterior < 0.01);
}

TEST_CASE(
    "MSAA beyond what the backend offers (--msaa), or not a power of two, is refused in one line before the solve",
    "[gl][camera]") {
  test::backend();
  const int most = gl::limits().cameraSamples;
  const std::string cornell = test::sourcePath("scenes/cornell/cornell.obj");
  std::vector<std::pair<std::string, std::string>> cases = {{"--msaa 3", "--msaa: 3 not in {1,2,4,8,16,32}"}};
  if (most < 32)
    cases.push_back({"--msaa " + std::to_string(2 * most), fmt::format("offers at most {} samples a pixel", most)});
  for (const auto& [flags, message] : cases) {
    const test::Run run = test::hemirad("solve " + cornell + " --quiet --out " + test::tempPath("m.exr") + " " + flags);
    INFO(flags << ": " << run.output);
    CHECK(run.exitCode == 2);
    CHECK_THAT(run.output, Catch::Contains(message));
    CHECK(std::count(run.output.begin(), run.output.end(), '\n') == 1);
  }
  // The report says what the image drew: the default (8, or the backend's most) however fine the
  // grid that fits one framebuffer (48^2 of 16 x 16 cells), or what --msaa asked.
  const std::string report = test::tempPath("msaa.json");
  for (const auto& [flags, samples] : std::vector<std::pair<std::string, int>>{
           {"", std::min(8, most)}, {"--msaa 1", 1}, {"--supersample 16", std::min(8, most)}}) {
    const test::Run run =
        test::hemirad("solve " + cornell + " --elements 300 --shots 20 --width 48 --height 48 --quiet --out " +
                      test::tempPath("m.exr") + " --report " + report + " " + flags);
    INFO(flags << ": " << run.output);
    REQUIRE(run.exitCode == 0);
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(report));
    CHECK(r["camera_image"]["msaa"] == samples);
  }
}

TEST_CASE("MSAA never meets the grid's shifted draws: one framebuffer of N x the image, else one sample a cell",
          "[camera]") {
  // 256^2: 4 x 4 and 8 x 8 cells of 8 samples fit one framebuffer (8.4 M and 33.6 M samples).
  CHECK(cameraPlan(256, 256, 4, 8, 16384).scale == 4);
  CHECK(cameraPlan(256, 256, 4, 8, 16384).samples == 8);
  CHECK(cameraPlan(256, 256, 8, 8, 16384).scale == 8);
  // 16 x 16 cells of 8 samples would be 134 M samples: the grid alone, at 8 x and 4 draws.
  const CameraPlan fine = cameraPlan(256, 256, 16, 8, 16384);
  CHECK(fine.samples == 1);
  CHECK(fine.scale == 8);
  CHECK(SupersampleGrid(16, fine.scale).draws() == 4);
  // Past the GPU's texture size, the same; and a single-sampled plan is the grid's own.
  CHECK(cameraPlan(2048, 2048, 8, 4, 8192).samples == 1);
  CHECK(cameraPlan(512, 512, 32, 1, 16384).scale == SupersampleGrid(32).scale());
  for (int n = 1; n <= 64; ++n)
    for (int m : {2, 4, 8}) {
      const CameraPlan p = cameraPlan(64, 48, n, m, 16384);
      INFO("N " << n << ", M " << m);
      CHECK((p.samples == 1 || SupersampleGrid(n, p.scale).draws() == 1));
    }
}
