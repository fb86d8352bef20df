// bench and experiment run from any folder (issue 17): their default and relative scene paths are
// found beside the binary (src/base/DataDir.h: the source tree for this build, PREFIX/share/hemirad
// installed, which tests/install/consumer.sh checks), never in the current directory.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;
namespace fs = std::filesystem;

TEST_CASE(
    "bench and experiment run from an empty folder, finding the shipped scenes beside the binary, and experiment's "
    "default output is a new folder, never an earlier run's",
    "[heavy][gl][cli]") {
  const std::string dir = test::tempPath("elsewhere");
  fs::create_directories(dir);
  test::Run bench = test::shell("cd " + dir + " && $HEMIRAD bench --elements 300 --split-shots 4 --json bench.json");
  INFO(bench.output);
  REQUIRE(bench.exitCode == 0);
  const nlohmann::json b = test::readJson(dir + "/bench.json");
  REQUIRE(b["rows"].size() == 1);
  CHECK(fs::equivalent(b["rows"][0]["scene"].get<std::string>(), test::sourcePath("scenes/cornell/cornell.obj")));
  CHECK(b["rows"][0]["convergence"].get<double>() >= 0.9);

  fs::create_directories(dir + "/hemirad-experiment");  // an earlier run's folder: left alone
  std::ofstream(dir + "/hemirad-experiment/summary.md") << "mine";
  test::Run experiment =
      test::shell("cd " + dir +
                  " && $HEMIRAD experiment --scenes scenes/cornell/cornell.obj --algorithms progressive --elements 150 "
                  "--reference-convergence 0.9 --fps 0.25 --frame-ms 5 --width 32 --height 32");
  INFO(experiment.output);
  REQUIRE(experiment.exitCode == 0);
  const std::string out = dir + "/hemirad-experiment-2/";
  for (const char* f : {"events.csv", "summary.md", "cornell_progressive.csv", "cornell_image_error.svg",
                        "cornell_visible_convergence.pdf"})
    CHECK(fs::exists(out + f));
  CHECK(test::readText(dir + "/hemirad-experiment/summary.md") == "mine");
  CHECK(!fs::exists(dir + "/docs"));
  CHECK_THAT(test::readText(out + "cornell_image_error.svg"), Contains(" --width 32 --height 32</dc:description>"));
  // A scene found neither here nor beside the binary is still one error naming the path as given.
  test::Run missing = test::shell("cd " + dir + " && $HEMIRAD bench --scenes scenes/none.obj --elements 300");
  CHECK(missing.exitCode == 2);
  CHECK(test::errorLines(missing.output) == 1);
  CHECK_THAT(missing.output, Contains("scenes/none.obj"));
}
