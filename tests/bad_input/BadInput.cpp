#include "tests/bad_input/BadInput.h"

#include <catch2/catch.hpp>
#include <filesystem>

#include "tests/support/Files.h"
#include "tests/support/Support.h"

namespace hemirad::test::bad_input {

namespace fs = std::filesystem;

Outputs::Outputs(const std::string& name) : dir(tempPath("out-" + name)) {
  fs::create_directories(dir);
  flags = " --out " + dir + "/view.exr --image " + dir + "/view.png --atlas " + dir + "/atlas.exr --ply " + dir +
          "/mesh.ply --report " + dir + "/report.json";
}

bool Outputs::empty() const { return fs::is_empty(dir); }

void expectRefused(const std::string& name, const std::string& args, const std::vector<std::string>& messages,
                   const std::string& env) {
  Outputs out(name);
  Run run = hemirad(args + out.flags, env);
  INFO("hemirad " << args << "\n" << run.output);
  CHECK(run.exitCode == 2);
  CHECK(errorLines(run.output) == 1);
  for (const auto& m : messages) CHECK_THAT(run.output, Catch::Contains(m));
  CHECK(out.empty());
}

std::string writeScene(const std::string& name, const std::string& obj, const std::string& mtl) {
  return test::writeScene("scene-" + name, obj, mtl);
}

}  // namespace hemirad::test::bad_input
