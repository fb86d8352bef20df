// Outputs behave like a Unix tool's (docs/solve.md#outputs): `--report -` is stdout; a FIFO,
// /dev/stdout or a symlink is written through, not replaced; names are checked before the scene
// is read; `--out x.png` is tone-mapped; the convergence history starts at exactly 0.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "src/base/OutputPaths.h"
#include "src/output/ImageFile.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;
namespace fs = std::filesystem;

namespace {
// A 2-shot solve of the smallest analytic scene, about 200 elements.
std::string quickSolve() {
  return "solve " + test::sourcePath("scenes/analytic/parallel_squares.obj") + " --elements 200 --shots 2 --quiet";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST_CASE("A report to - or /dev/stdout is the JSON on stdout, with nothing else there", "[cli]") {
  for (const char* target : {"-", "/dev/stdout"}) {
    INFO(target);
    const std::string got = test::tempPath(std::string("stdout-report") + (target[0] == '-' ? "1" : "2") + ".json");
    test::Run run = test::shell("$HEMIRAD " + quickSolve() + " --report " + target + " 2>/dev/null | cat > " + got);
    REQUIRE(run.exitCode == 0);
    const nlohmann::json report = nlohmann::json::parse(slurp(got));  // throws on anything but the JSON
    CHECK(report["shots"] == 2);
  }
}

TEST_CASE("A FIFO or a symlink as an output is written through, not replaced by a renamed file", "[cli]") {
  const std::string dir = test::tempPath("write-through");
  fs::create_directories(dir);
  // FIFO: a reader drains it while hemirad writes; the FIFO must still be a FIFO afterwards.
  test::Run fifo =
      test::shell("cd " + dir + " && mkfifo r.fifo && (timeout 60 cat r.fifo > got.json 2>/dev/null &) && $HEMIRAD " +
                  quickSolve() + " --report r.fifo");
  INFO(fifo.output);
  REQUIRE(fifo.exitCode == 0);
  CHECK(fs::is_fifo(dir + "/r.fifo"));
  for (int i = 0; i < 100 && slurp(dir + "/got.json").empty(); ++i) test::shell("sleep 0.05");
  CHECK(nlohmann::json::parse(slurp(dir + "/got.json"))["shots"] == 2);
  // Symlink: the file it names gets the image; the link stays a link.
  fs::create_directories(dir + "/real");
  fs::create_symlink("real/view.png", dir + "/link.png");
  test::Run link = test::hemirad(quickSolve() + " --width 64 --height 64 --image " + dir + "/link.png");
  INFO(link.output);
  REQUIRE(link.exitCode == 0);
  CHECK(fs::is_symlink(dir + "/link.png"));
  CHECK(readImage(dir + "/real/view.png").width == 64);
}

TEST_CASE("Bad output names are refused before the scene is read, naming the flag", "[cli][bad-input]") {
  // The scene is broken too: the output name must be what is reported, so it was checked first.
  const std::string broken = test::writeScene("broken-and-bad-name", "v 0 0 0\nf 1 2 9\n", "");
  const std::string dir = test::tempPath("bad-names");
  fs::create_directories(dir);
  for (auto [flag, name, message] :
       {std::tuple<std::string, std::string, std::string>{"--image", "x", "no file extension"},
        {"--image", "x.exr", "'.exr' is not a format it writes; the file name must end in .png"},
        {"--out", "x.tiff", "must end in .exr or .png"},
        {"--atlas", "a.png", "must end in .exr"},
        {"--ply", "m.obj", "must end in .ply"},
        {"--gltf", "s.gltf", "'.gltf' is not a format it writes; the file name must end in .glb"},
        {"--report", "r.txt", "must end in .json (or be - for stdout)"}}) {
    test::Run run = test::hemirad("solve " + broken + " --quiet " + flag + " " + dir + "/" + name);
    INFO(run.output);
    CHECK(run.exitCode == 2);
    CHECK(test::errorLines(run.output) == 1);
    CHECK_THAT(run.output, Contains(flag + " " + dir + "/" + name) && Contains(message));
  }
  // The viewer's screenshot is a PNG, checked before any scene or window.
  test::Run view = test::hemirad("view " + broken + " --screenshot " + dir + "/shot.jpg");
  INFO(view.output);
  CHECK(view.exitCode == 2);
  CHECK(test::errorLines(view.output) == 1);
  CHECK_THAT(view.output, Contains("--screenshot " + dir + "/shot.jpg") && Contains("the file name must end in .png"));
  CHECK(fs::is_empty(dir));
}

TEST_CASE("A solve without any output warns that only the summary line shows the result", "[cli]") {
  test::Run run = test::hemirad(quickSolve());
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK_THAT(run.output, Contains("hemirad: warning: no output flag"));
  CHECK_FALSE(Catch::Contains("warning").match(test::hemirad(quickSolve() + " --report /dev/null").output));
}

TEST_CASE(
    "A PNG named by --out is the tone-mapped render, pixel for pixel the --image PNG, not linear values clipped to "
    "black",
    "[cli]") {
  const std::string dir = test::tempPath("out-png");
  fs::create_directories(dir);
  test::Run run = test::hemirad(quickSolve() + " --width 64 --height 64 --out " + dir + "/out.png --image " + dir +
                                "/image.png --report " + dir + "/r.json");
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  const Image out = readImage(dir + "/out.png"), image = readImage(dir + "/image.png");
  CHECK(out.rgb == image.rgb);
  // Exposed: the lit emitter and receiver are mid-grey or brighter (measured 0.093 after 2 shots,
  // without the ambient term; a linear render clipped to 8 bits would be near 0).
  CHECK(test::meanPixel(out) > 0.05);
}

TEST_CASE("The convergence history starts at exactly 0, has one entry per pass and never decreases", "[cli]") {
  const std::string report = test::tempPath("history.json");
  test::Run run = test::hemirad("solve " + test::sourcePath("scenes/cornell/cornell.obj") +
                                " --elements 600 --shots 40 --quiet --report " + report);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  const nlohmann::json r = test::readJson(report);
  const auto h = r["convergence_history"].get<std::vector<std::pair<unsigned, float>>>();
  const unsigned passes = (40 + r["shooters_per_pass"].get<unsigned>() - 1) / r["shooters_per_pass"].get<unsigned>();
  REQUIRE(h.size() >= 2);
  CHECK(h.size() <= passes + 2);  // where each pass began, and the end
  CHECK(h.front() == std::pair<unsigned, float>{0, 0.0f});
  for (std::size_t i = 1; i < h.size(); ++i) {
    CHECK(h[i].first > h[i - 1].first);
    CHECK(h[i].second >= h[i - 1].second);
  }
  CHECK(h.back().first == 40);
  CHECK(h.back().second == Approx(r["convergence"].get<double>()));
}

TEST_CASE("A default output folder is always a new one: NAME, then NAME-2, NAME-3, never an earlier run's", "[cpu]") {
  const std::string base = test::tempPath("fresh") + "/hemirad-experiment";
  fs::create_directories(fs::path(base).parent_path());
  CHECK(freshFolder(base) == base);
  fs::create_directories(base);
  CHECK(freshFolder(base) == base + "-2");
  fs::create_directories(base + "-2");
  std::ofstream(base + "-3");  // a file of that name is taken too
  CHECK(freshFolder(base) == base + "-4");
}
