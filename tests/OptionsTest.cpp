// The option table (issue 13): every command's flags come from it, docs/cli.md is generated
// from it, mistyped names get the closest valid one, and `solve --method` selects the solver.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "src/cli/Commands.h"
#include "src/options/Options.h"
#include "src/options/Suggest.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

using hemirad::test::count;

namespace {

// Exit 2 and exactly one error line, containing `message`.
void expectOneError(const std::string& args, const std::string& message) {
  test::Run run = test::hemirad(args);
  INFO("hemirad " << args << "\n" << run.output);
  CHECK(run.exitCode == 2);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains(message));
}

const std::string kOptionsScene = test::sourcePath("scenes/analytic/parallel_squares.obj");

}  // namespace

TEST_CASE("Edit distance counts insertions, deletions, substitutions and swapped neighbours", "[cpu][cli]") {
  using options::editDistance;
  CHECK(editDistance("", "") == 0);
  CHECK(editDistance("kitten", "sitting") == 3);
  CHECK(editDistance("texel-sise", "texel-size") == 1);
  CHECK(editDistance("scnees", "scenes") == 1);  // a swap is one edit
  CHECK(editDistance("shots", "") == 5);
  CHECK(options::closest("--texel-sise", {"--elements", "--texel-size", "--shots"}) == "--texel-size");
  CHECK(options::closest("--sup", {"--supersample", "--shots"}) == "--supersample");  // a prefix
  CHECK(options::closest("--frobnicate", {"--elements", "--texel-size", "--shots"}).empty());
}

TEST_CASE("Every command builds its flags from the table and the table names each flag once", "[cpu][cli]") {
  Commands commands;  // throws std::logic_error for a flag missing from the table
  std::set<std::string> names;
  for (const options::Flag& f : options::table()) {
    INFO(f.name);
    CHECK(names.insert(f.name).second);
  }
  for (const CLI::App* cmd : commands.app.get_subcommands({}))
    for (const CLI::Option* o : cmd->get_options())
      for (const std::string& l : o->get_lnames()) {
        INFO(cmd->get_name() << " --" << l);
        if (l != "help") CHECK(names.count("--" + l) == 1);
      }
}

TEST_CASE("docs/cli.md is what `hemirad docs cli` prints from the table", "[cli]") {
  test::Run run = test::hemirad("docs cli");
  REQUIRE(run.exitCode == 0);
  std::ifstream in(test::sourcePath("docs/cli.md"));
  std::stringstream committed;
  committed << in.rdbuf();
  INFO("regenerate with: build/hemirad docs cli > docs/cli.md");
  CHECK(run.output == committed.str());
  CHECK_THAT(run.output, Contains("| `--method` |"));
}

TEST_CASE("A mistyped flag or subcommand is one error naming the closest valid one", "[cli][bad-input]") {
  expectOneError("solve " + kOptionsScene + " --texel-sise 3", "did you mean --texel-size?");
  expectOneError("solve " + kOptionsScene + " --converj=0.5", "did you mean --converge?");
  expectOneError("solv " + kOptionsScene, "unknown subcommand 'solv': did you mean solve?");
  expectOneError("validate " + kOptionsScene + " --shots 3", "--shots is not a flag of hemirad validate");
  expectOneError("bench --scnees x.obj", "did you mean --scenes?");
}

TEST_CASE("The --converge flag is checked the same in every command that takes it", "[heavy][cli][bad-input]") {
  for (const std::string& command : {"solve " + kOptionsScene, "view " + kOptionsScene, std::string("bench")})
    for (const std::string value : {"0", "1", "nan", "x"})
      expectOneError(command + " --converge " + value, "--converge: must be in (0, 1), not '" + value + "'");
}

TEST_CASE("validate takes --gpu, the EGL device index, as solve does", "[cli][backend]") {
  expectOneError("validate " + kOptionsScene + " --gpu -1", "--gpu");
  test::Run run = test::hemirad("validate " + kOptionsScene + " --backend egl --gpu 99 --levels 0 --shooters 1");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("egl: GPU 99 not usable"));
}

TEST_CASE("Solve refuses atlas outputs of --method instant and unknown methods, before the scene is read",
          "[cli][bad-input]") {
  // An OBJ without faces: reading it would be an error of its own.
  const std::string dir = test::tempPath("method");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/empty.obj") << "# nothing\n";
  expectOneError("solve " + dir + "/empty.obj --method instant --ply " + dir + "/x.ply",
                 "--atlas, --ply and --gltf need radiosity per element; --method instant shades camera pixels only");
  expectOneError("solve " + dir + "/empty.obj --method gauss-seidel", "--method");
}

TEST_CASE("Solve with --method progressive gives the bitwise result of the default and the report names the method",
          "[heavy][cli]") {
  auto report = [](const std::string& flags) {
    const std::string path = test::tempPath("method" + std::to_string(flags.size()) + ".json");
    test::Run run = test::hemirad("solve " + test::sourcePath("scenes/cornell/cornell.obj") +
                                  " --elements 600 --shots 48 --quiet " + flags + " --report " + path);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return nlohmann::json::parse(std::ifstream(path));
  };
  const nlohmann::json plain = report(""), progressive = report("--method progressive");
  CHECK(plain["method"] == "progressive");
  CHECK(progressive["method"] == "progressive");
  CHECK(plain["shots"] == 48);
  CHECK(progressive["radiosity_hash"] == plain["radiosity_hash"]);
}
