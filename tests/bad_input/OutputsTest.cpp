// Unwritable outputs (docs/errors.md): an output path in a missing folder, under a file, or
// naming a folder is one error naming the flag, before any solving.
#include <catch2/catch.hpp>
#include <filesystem>
#include <utility>

#include "tests/bad_input/BadInput.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using namespace hemirad::test::bad_input;
using Catch::Contains;
using hemirad::test::count;
namespace fs = std::filesystem;

TEST_CASE(
    "Bad input: an output path in a missing folder or naming a folder is one error naming the flag before solving",
    "[cli][bad-input]") {
  std::string obj = writeScene("unwritable", kQuad + "f 1 2 3 4\n");
  std::string file = fs::path(obj).parent_path() / "m.mtl";  // a file, used as a folder below
  std::string folder = test::tempPath("a-folder");
  fs::create_directories(folder);
  for (auto [flag, path] : {std::pair<std::string, std::string>{"--out", "/no/such/folder/x.exr"},
                            {"--image", file + "/x.png"},
                            {"--report", folder},
                            {"--atlas", "/no/such/a.exr"},
                            {"--ply", folder},
                            {"--gltf", "/no/such/folder/x.glb"}}) {
    test::Run run = test::hemirad(solve(obj) + " " + flag + " " + path);
    INFO(run.output);
    CHECK(run.exitCode == 2);
    CHECK(count(run.output, "hemirad: error:") == 1);
    CHECK_THAT(run.output, Contains(flag + " " + path));
  }
  CHECK(fs::is_empty(folder));
}

TEST_CASE("Bad input: figures without python3 or without matplotlib are one error before any work, nothing written",
          "[cli][bad-input]") {
  std::string obj = writeScene("noplot", kQuad + "f 1 2 3 4\n");
  // A python3 that cannot import matplotlib: the system one without its site packages.
  std::string bare = test::writeTempFile("bare-python3", "#!/bin/sh\nexec /usr/bin/python3 -I -S \"$@\"\n");
  fs::permissions(bare, fs::perms::owner_all);
  for (auto [python, message] : {std::pair<std::string, std::string>{"/no/such/python3", "cannot run /no/such/python3"},
                                 {bare, "No module named 'matplotlib'"}}) {
    const std::string figures = test::tempPath("noplot-figures"), report = test::tempPath("noplot.json");
    test::Run run = test::hemirad("validate " + obj + " --levels 0 --report " + report + " --figures " + figures,
                                  "HEMIRAD_PYTHON=" + python);
    INFO(run.output);
    CHECK(run.exitCode == 2);
    CHECK(count(run.output, "hemirad: error:") == 1);
    CHECK_THAT(run.output, Contains("python3-matplotlib") && Contains(message));
    CHECK(!fs::exists(figures));
    CHECK(!fs::exists(report));
  }
}

TEST_CASE("Bad input: --gltf whose lightmap beside it cannot be written is one error naming it, and nothing is written",
          "[cli][bad-input]") {
  std::string obj = writeScene("gltf-sidecar", kQuad + "f 1 2 3 4\n");
  std::string dir = test::tempPath("gltf-sidecar-out");
  fs::create_directories(dir + "/x.lightmap.exr");  // a folder where the EXR must go
  test::Run run = test::hemirad(solve(obj) + " --gltf " + dir + "/x.glb");
  INFO(run.output);
  CHECK(run.exitCode == 2);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("--gltf " + dir + "/x.lightmap.exr"));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);  // the folder only
}
