// `hemirad view` run headless under Xvfb: the window shows what `solve` computes, each
// algorithm runs, and without a display it fails cleanly. CI installs xvfb: without xvfb-run
// these tests fail rather than skip.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include "src/output/ImageFile.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

const std::string kViewerScene = test::sourcePath("scenes/cornell/cornell.obj");

// `hemirad view ARGS` on a fresh virtual display; exit 97 says xvfb-run is missing.
test::Run viewUnderXvfb(const std::string& args) {
  return test::shell(
      "command -v xvfb-run >/dev/null || { echo 'xvfb-run not found: install xvfb and xauth'; exit 97; }\n"
      "xvfb-run -a -s '-screen 0 1024x768x24' \"$HEMIRAD\" view " +
      args);
}

// The viewer's last frame after `view ARGS` and solve's --image after `solve ARGS` (one sample a
// pixel, as the viewer draws); the viewer's summary line must contain `summary`.
std::pair<Image, Image> viewAndSolve(const std::string& viewArgs, const std::string& solveArgs,
                                     const std::string& summary, const std::string& name) {
  const std::string shown = test::tempPath(name + "-view.png"), solved = test::tempPath(name + "-solve.png");
  test::Run view = viewUnderXvfb(viewArgs + " --screenshot " + shown);
  INFO(view.output);
  REQUIRE(view.exitCode == 0);
  CHECK_THAT(view.output, Contains(summary));
  test::Run solve = test::hemirad("solve " + solveArgs + " --supersample 1 --msaa 1 --quiet --image " + solved);
  INFO(solve.output);
  REQUIRE(solve.exitCode == 0);
  return {readImage(shown), readImage(solved)};
}

float maxDifference(const Image& a, const Image& b) {
  REQUIRE(a.rgb.size() == b.rgb.size());
  float maxDiff = 0;
  for (size_t i = 0; i < a.rgb.size(); ++i) maxDiff = std::max(maxDiff, std::abs(a.rgb[i] - b.rgb[i]));
  return maxDiff;
}

}  // namespace

TEST_CASE("The viewer under Xvfb shows the same picture as solve after the same shots", "[viewer][heavy]") {
  const std::string common = kViewerScene + " --elements 1500 --width 160 --height 120";
  // The viewer previews with the ambient term; a solve's images leave it out unless asked. The
  // viewer's stop rule is 0.999 (Viewer.h), and the stop rule sets auto's refinement and blocks.
  const auto [a, b] =
      viewAndSolve(common + " --frame-shots 8 --frame-count 5", common + " --shots 40 --converge 0.999 --ambient on",
                   "hemirad view: progressive, 40 shots", "progressive");
  REQUIRE(a.width == 160);
  REQUIRE(a.height == 120);
  REQUIRE(b.width == a.width);
  REQUIRE(b.height == a.height);
  // Exposure maps the 95th-percentile lit luminance to 1: a lit box averages far above black.
  CHECK(test::meanPixel(a) > 0.2);
  const float maxDiff = maxDifference(a, b);
  // The same passes, renderer and tone map; glDrawPixels then glReadPixels of 8-bit values on an
  // 8-bit window change nothing (measured: 0). One LSB is left for a GLX path that dithers.
  CHECK(maxDiff <= 1.0f / 255 + 1e-6f);
}

TEST_CASE("Each algorithm runs in the viewer for exactly frame-shots x frame-count shots", "[heavy][viewer]") {
  for (std::string algorithm : {"progressive", "importance", "perspective"}) {
    const std::string shot = test::tempPath("viewer-" + algorithm + ".png");
    test::Run view = viewUnderXvfb(kViewerScene + " --elements 600 --width 64 --height 48 --algorithm " + algorithm +
                                   " --frame-shots 16 --frame-count 3 --screenshot " + shot);
    INFO(algorithm << "\n" << view.output);
    REQUIRE(view.exitCode == 0);
    std::smatch m;
    REQUIRE(std::regex_search(view.output, m,
                              std::regex("hemirad view: (\\w+), (\\d+) shots, convergence ([0-9.]+), (\\d+) frames")));
    CHECK(m[1] == algorithm);
    CHECK(m[2] == "48");
    CHECK(std::stod(m[3]) > 0);
    CHECK(m[4] == "3");
    CHECK(test::meanPixel(readImage(shot)) > 0.2);
  }
}

TEST_CASE("The viewer shows instant radiosity as solve --method instant renders it, interleaved",
          "[heavy][viewer][instant]") {
  const std::string common =
      kViewerScene + " --method instant --vpls 64 --shadow-res 32 --interleave 2 --width 64 --height 48";
  const auto [a, b] =
      viewAndSolve(common + " --frame-count 3", common,
                   "hemirad view: instant, 64 VPLs, deferred shading, interleave 2, 3 frames", "instant");
  CHECK(test::meanPixel(a) > 0.2);
  CHECK(maxDifference(a, b) <= 1.0f / 255 + 1e-6f);  // as the progressive view: the same render and tone map
  // Refused before any window opens: no display needed.
  test::Run refused = test::shell("env -u DISPLAY \"$HEMIRAD\" view " + kViewerScene + " --interleave 2");
  CHECK(refused.exitCode == 2);
  CHECK_THAT(refused.output, Contains("--interleave is for --method instant"));
}

TEST_CASE("Without a display the viewer fails with one error line", "[viewer]") {
  const std::string shot = test::tempPath("never.png");
  test::Run run = test::shell("env -u DISPLAY -u WAYLAND_DISPLAY \"$HEMIRAD\" view " + kViewerScene +
                              " --elements 600 --frame-count 1 --screenshot " + shot);
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(test::errorLines(run.output) == 1);
  CHECK_THAT(run.output, Contains("hemirad: error: hemirad view: cannot open a window"));
  CHECK_THAT(run.output, Contains("xvfb-run"));
  CHECK_FALSE(std::filesystem::exists(shot));

  // Bad input is found before any window is opened: exit 2, as for solve.
  const std::string dark = test::writeScene("dark", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl grey\nf 1 2 3\n",
                                            "newmtl grey\nKd 0.5 0.5 0.5\n");
  for (auto [scene, message] : {std::pair{std::string("/no/such.obj"), "such.obj"}, {dark, "no emitter"}}) {
    test::Run bad = test::shell("env -u DISPLAY \"$HEMIRAD\" view " + scene + " --screenshot " + shot);
    INFO(bad.output);
    CHECK(bad.exitCode == 2);
    CHECK(test::errorLines(bad.output) == 1);
    CHECK_THAT(bad.output, Contains(message));
    CHECK_FALSE(std::filesystem::exists(shot));
  }
}
