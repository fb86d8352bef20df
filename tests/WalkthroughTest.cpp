// Camera paths and walkthroughs: keyframes parse and blend, and `solve --camera-path` writes a
// frame and a CSV row per frame, reproducibly with a shot budget per frame.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/base/Error.h"
#include "src/walk/CameraPath.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
std::vector<std::vector<std::string>> readFramesCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) rows.back().push_back(cell);
  }
  return rows;
}
// frames.csv's columns that a shots-per-frame budget makes reproducible: all but the times.
constexpr std::size_t kReproducibleColumns[] = {0, 1, 3, 4, 5, 6, 7, 8, 9, 10, 11};
}  // namespace

TEST_CASE("Camera path keyframes inherit the keys they leave out and blend linearly between", "[cpu]") {
  Camera base;
  base.up = {1, 0, 0};
  const CameraPath path = readCameraPath(
      test::writeTempFile("blend.path",
                          "# a comment\n0 eye=0,0,10 target=0,0,0 fov=40\n\n2 eye=4,0,10  # moves\n4 fov=20\n"),
      base);
  REQUIRE(path.keys.size() == 3);
  CHECK(path.duration() == 4.0);
  CHECK(path.keys[1].camera.target == glm::dvec3(0.0));  // inherited
  CHECK(path.keys[2].camera.eye == glm::dvec3(4, 0, 10));
  CHECK(path.keys[0].camera.up == glm::dvec3(1, 0, 0));  // from the base camera
  const Camera mid = path.at(1.0), later = path.at(3.0);
  CHECK(mid.eye.x == Approx(2.0));
  CHECK(mid.fovY == Approx(40.0));
  CHECK(later.fovY == Approx(30.0));
  CHECK(path.at(-1).eye == path.keys[0].camera.eye);
  CHECK(path.at(99).fovY == Approx(20.0));
}

TEST_CASE("Malformed camera paths name the file, the line and the problem", "[cpu]") {
  Camera base;
  auto fails = [&](const std::string& name, const std::string& text, const std::string& message) {
    const std::string path = test::writeTempFile(name, text);
    CHECK_THROWS_WITH(readCameraPath(path, base), Catch::Contains(message));
  };
  fails("order.path", "0 eye=0,0,1\n2 eye=0,0,2\n1 eye=0,0,3\n", "order.path:3: keyframe times must increase");
  fails("time.path", "soon eye=0,0,1\n", "time.path:1: a keyframe starts with its time in seconds, not 'soon'");
  fails("key.path", "0 eye=0,0,1\n1 pos=1,2,3\n", "key.path:2: unknown camera key 'pos'");
  fails("empty.path", "# nothing\n", "no keyframes");
  CHECK_THROWS_AS(readCameraPath("/no/such.path", base), InputError);
}

TEST_CASE(
    "A walkthrough writes a frame and a CSV row per frame, reproducibly with shots per frame, and shows its progress",
    "[heavy][cli][walkthrough]") {
  const std::string scene = test::sourcePath("scenes/cornell/cornell.obj");
  const std::string path = test::writeTempFile(
      "turn.path", "0 eye=278,273,-800 target=278,273,0 fov=39.3\n0.5 fov=39.3\n1 target=556,0,559.2 fov=20\n");
  for (const std::string algorithm : {"progressive", "importance", "perspective"}) {
    INFO(algorithm);
    // Reproducibility is checked on the perspective-driven run, the one with the most state.
    const bool twice = algorithm == "perspective";
    const std::string a = test::tempPath("walk_a_" + algorithm), b = test::tempPath("walk_b_" + algorithm);
    const std::string flags = " --elements 600 --algorithm " + algorithm + " --camera-path " + path +
                              " --fps 4 --frame-shots 12 --shooters-per-pass 4 --item-res 128 --width 48 --height 48 "
                              "--reference-convergence 0.9" +
                              std::string(twice ? " --quiet" : "");
    test::Run run = test::shell("$HEMIRAD solve " + scene + flags + " --frames " + a +
                                (twice ? " && $HEMIRAD solve " + scene + flags + " --frames " + b : std::string()));
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    const auto rows = readFramesCsv(a + "/frames.csv"), again = readFramesCsv((twice ? b : a) + "/frames.csv");
    REQUIRE(rows.size() == 6);  // header + frames at 0, 0.25, ... 1 s
    CHECK(rows[0][0] == "frame");
    CHECK(rows[0].back() == "shown_rms");
    for (int f = 0; f < 5; ++f) {
      CHECK(std::filesystem::exists(a + "/frame_000" + std::to_string(f) + ".png"));
      CHECK(std::stoul(rows[f + 1][3]) <= 12u * (f + 1));  // radiosity shots: 3 passes of 4 a frame at most
      for (std::size_t c : kReproducibleColumns) CHECK(rows[f + 1][c] == again[f + 1][c]);
    }
    CHECK(std::stoul(rows[5][3]) > std::stoul(rows[1][3]));
    if (!twice) {  // not silent for minutes: the reference solve and the frames report progress
      CHECK(run.output.find("hemirad: the reference solve, to convergence 0.9") != std::string::npos);
      CHECK(run.output.find("hemirad: frame 5 of 5") != std::string::npos);
    }
    // While the camera stands still (0 to 0.5 s), more of the light it sees arrives.
    CHECK(std::stod(rows[3][7]) > std::stod(rows[1][7]));
    CHECK(std::stod(rows[3][8]) < std::stod(rows[1][8]));
  }
}

TEST_CASE("Walkthrough flags come together: a path needs a frames folder and a budget of one kind", "[heavy][cli]") {
  const std::string scene = test::sourcePath("scenes/cornell/cornell.obj");
  const std::string path = test::sourcePath("scenes/cornell/cornell.path");
  for (const std::string& args :
       std::vector<std::string>{"--camera-path " + path, "--frames /tmp/x",
                                "--camera-path " + path + " --frames /tmp/x --frame-ms 10 --frame-shots 4",
                                "--camera-path " + test::writeTempFile("bad.path", "0 eye=1\n") + " --frames /tmp/x"}) {
    test::Run run = test::hemirad("solve " + scene + " " + args);
    INFO(args << "\n" << run.output);
    CHECK(run.exitCode == 2);
    CHECK(run.output.find("hemirad: error:") != std::string::npos);
  }
}

TEST_CASE(
    "hemirad-bench experiment, the lean binary for GPU machines, walks as hemirad experiment does, without figures",
    "[heavy][cli][walkthrough]") {
  // Shots per frame make the runs reproducible: every column but the times must agree.
  const std::string flags = " experiment --scenes " + test::sourcePath("scenes/building/building_4.obj") +
                            " --algorithms perspective --elements 300 --camera-path " +
                            test::sourcePath("scenes/building/building_4.path") +
                            " --fps 0.5 --frame-shots 8 --width 32 --height 32 --reference-convergence 0.8 --out-dir ";
  const std::string full = test::tempPath("experiment_full"), lean = test::tempPath("experiment_lean");
  test::Run run =
      test::shell("$HEMIRAD" + flags + full + " && \"$(dirname \"$HEMIRAD\")/hemirad-bench\"" + flags + lean);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  const auto a = readFramesCsv(full + "/building_4_perspective.csv"),
             b = readFramesCsv(lean + "/building_4_perspective.csv");
  REQUIRE(a.size() > 2);
  REQUIRE(a.size() == b.size());
  for (std::size_t r = 0; r < a.size(); ++r)
    for (std::size_t c : kReproducibleColumns) CHECK(a[r][c] == b[r][c]);
  CHECK(std::filesystem::exists(lean + "/summary.md"));
  CHECK(std::filesystem::exists(full + "/building_4_error_vs_shots.svg"));
  CHECK_FALSE(std::filesystem::exists(lean + "/building_4_error_vs_shots.svg"));
}
