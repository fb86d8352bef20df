// Backend failures (docs/errors.md): a GL library or device that is not there is one error
// line and exit code 1, or, under --backend auto, a warning and the OSMesa fallback.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/bad_input/BadInput.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using namespace hemirad::test::bad_input;
using Catch::Contains;
using hemirad::test::count;

// ---- backends

TEST_CASE("Backend failure: a missing OSMesa library is one error naming the file, exit 1, no output",
          "[cli][backend]") {
  std::string obj = writeScene("no-osmesa", kQuad + "f 1 2 3 4\n");
  Outputs out("no-osmesa");
  test::Run run = test::hemirad(solve(obj) + out.flags, "HEMIRAD_OSMESA_LIBRARY=/no/such/libOSMesa.so.8");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output,
             Contains("hemirad: error: osmesa: cannot load HEMIRAD_OSMESA_LIBRARY=/no/such/libOSMesa.so.8"));
  CHECK(out.empty());
}

TEST_CASE("Backend failure: a missing EGL library with --backend egl is one error naming the file, exit 1",
          "[cli][backend]") {
  std::string obj = writeScene("no-egl", kQuad + "f 1 2 3 4\n");
  Outputs out("no-egl");
  test::Run run = test::hemirad(solve(obj) + " --backend egl" + out.flags, "HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("hemirad: error: egl: cannot load HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1"));
  CHECK(out.empty());
}

TEST_CASE("Backend failure: --backend auto without an EGL library warns and falls back to OSMesa", "[cli][backend]") {
  std::string obj = writeScene("auto", kQuad + "f 1 2 3 4\n");
  std::string report = test::tempPath("auto.json");
  test::Run run =
      test::hemirad(solve(obj) + " --backend auto --report " + report, "HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1");
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(count(run.output, "hemirad: warning:") == 1);
  CHECK_THAT(run.output,
             Contains("hemirad: warning: --backend auto: egl: cannot load HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1"));
  CHECK_THAT(run.output, Contains("falling back to osmesa"));
  CHECK(nlohmann::json::parse(std::ifstream(report))["backend"] == "osmesa");
}

TEST_CASE("Backend failure: an EGL device index that does not exist is one error naming it, exit 1", "[cli][backend]") {
  std::string obj = writeScene("no-device", kQuad + "f 1 2 3 4\n");
  Outputs out("no-device");
  test::Run run = test::hemirad(solve(obj) + " --backend egl --gpu 99" + out.flags);
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("egl: GPU 99 not usable"));
  CHECK(out.empty());
}
