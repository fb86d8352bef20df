// The contract every radiosity method (src/method/MethodUnit.h) keeps, generated over the
// registry rather than copied per method: its flags are its own (another method's is one error
// naming it), and a killed solve resumes from its checkpoint to the bitwise result of an
// uninterrupted one (or, without checkpoints, --checkpoint is refused). A method added to
// src/method/Registry.cpp is tested here with no line added.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "src/base/Error.h"
#include "src/bench/Bench.h"
#include "src/cli/Commands.h"
#include "src/method/MethodChoice.h"
#include "src/method/MethodFlag.h"
#include "src/method/Registry.h"
#include "src/options/Options.h"
#include "src/output/ImageFile.h"
#include "src/output/Report.h"
#include "src/solver/Solver.h"
#include "src/viewer/ViewerWorker.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

const std::string kScene = test::sourcePath("scenes/cornell/cornell.obj");

// A value the option table accepts for `flag`: one of the names its check lists, a number, or a
// file; empty for a switch.
std::string acceptedValue(const std::string& flag) {
  const options::Flag& f = options::flag(flag);
  if (f.value.empty()) return "";
  std::vector<std::string> candidates;
  const std::string names = f.check.get_description();
  for (std::size_t a = 0, b; a <= names.size(); a = b + 1) {
    b = std::min(names.find('|', a), names.size());
    candidates.push_back(names.substr(a, b - a));
  }
  for (const char* n : {"1", "0.5", "16"}) candidates.push_back(n);
  candidates.push_back(kScene);
  for (const std::string& c : candidates)
    if (std::string checked = c; !c.empty() && f.check(checked).empty()) return c;  // the check may convert
  FAIL("no value found that " << flag << " accepts");
  return "";
}

// `flag` with a value, and any flag it needs (--camera-path needs --frames).
std::string given(const CLI::App& solve, const std::string& flag) {
  std::string args = flag + " " + acceptedValue(flag);
  for (const CLI::Option* needed : solve.get_option(flag)->get_needs())
    args += " " + needed->get_name() + " " + acceptedValue(needed->get_name());
  return args;
}

// Parses `solve SCENE ARGS` and settles it as `hemirad` does before any work.
void settleSolve(const std::string& args) {
  Commands commands;
  commands.app.parse("hemirad solve " + kScene + " " + args, true);
  commands.settle();
}

struct Report {
  nlohmann::json json;
  std::string hash() const { return json.contains("radiosity_hash") ? json["radiosity_hash"] : json["image_hash"]; }
};

// The method of `methods` called `name` (GENERATE runs a test once per registered name).
const MethodUnit& named(const std::vector<std::unique_ptr<MethodUnit>>& methods, const std::string& name) {
  return **std::find_if(methods.begin(), methods.end(), [&](const auto& m) { return m->name() == name; });
}

Report solveReport(const MethodUnit& method, const std::string& flags, const std::string& name) {
  const std::string path = test::tempPath("contract-" + method.name() + "-" + name + ".json");
  test::Run run = test::hemirad("solve " + kScene + " --quiet --method " + method.name() + " " + method.quickFlags() +
                                " " + flags + " --report " + path);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  return {test::readJson(path)};
}

}  // namespace

TEST_CASE("Every method refuses each flag only other methods take with one error naming the flag and its methods",
          "[cli][bad-input]") {
  Commands commands;
  const CLI::App& solve = *commands.app.get_subcommand("solve");
  const MethodChoice choice;
  for (const auto& method : makeMethods()) {
    const std::vector<MethodFlag> own = method->flags();
    for (const std::string& flag : choice.flagNames()) {
      if (std::any_of(own.begin(), own.end(), [&](const MethodFlag& f) { return f.name == flag; })) continue;
      const std::string args = "--method " + method->name() + " " + given(solve, flag);
      INFO("solve " << args);
      CHECK_THROWS_WITH(settleSolve(args), Contains(flag + " is for --method ") && Contains(", not " + method->name()));
    }
  }
}

TEST_CASE("Every method takes each of its own flags, and solve declares every method flag once", "[cli]") {
  Commands commands;
  const CLI::App& solve = *commands.app.get_subcommand("solve");
  for (const std::string& flag : MethodChoice().flagNames()) CHECK(solve.get_option_no_throw(flag) != nullptr);
  for (const auto& method : makeMethods()) {
    std::string args = "--method " + method->name();
    for (const MethodFlag& f : method->flags()) args += " " + given(solve, f.name);
    INFO("solve " << args);
    CHECK_NOTHROW(settleSolve(args));
  }
}

TEST_CASE(
    "Every method killed in a checkpoint write resumes from the previous one to the bitwise result of an "
    "uninterrupted solve, or refuses --checkpoint before reading the scene",
    "[heavy][cli][checkpoint]") {
  const std::string name = GENERATE(from_range(methodNames()));
  const std::vector<std::unique_ptr<MethodUnit>> methods = makeMethods();
  const MethodUnit& method = named(methods, name);
  INFO("--method " << method.name());
  if (!method.checkpoints()) {
    const std::string empty = test::tempPath("contract-empty.obj");  // reading it would be an error of its own
    std::ofstream(empty) << "# no faces\n";
    test::Run refused = test::hemirad("solve " + empty + " --method " + method.name() + " --checkpoint " +
                                      test::tempPath("contract.ckpt"));
    INFO(refused.output);
    CHECK(refused.exitCode == 2);
    CHECK_THAT(refused.output, Contains("hemirad: error:") && Contains("checkpoint"));
    return;
  }
  // The test hook SIGKILLs the solve half way through its second checkpoint write: the first,
  // at 16 shots, stays whole, and the half-written one has a .tmp name.
  const std::string ck = test::tempPath("killed-" + method.name() + ".ckpt");
  const Report whole = solveReport(method, "--shots 48", "whole");
  test::Run killed =
      test::hemirad("solve " + kScene + " --quiet --method " + method.name() + " " + method.quickFlags() +
                        " --shots 48 --checkpoint " + ck + " --checkpoint-every 16",
                    "HEMIRAD_TEST_KILL_IN_CHECKPOINT=2");
  INFO(killed.output);
  REQUIRE(killed.exitCode == 128 + 9);
  const std::string stem = std::filesystem::path(ck).stem().string();
  for (const auto& f : std::filesystem::directory_iterator(std::filesystem::path(ck).parent_path()))
    if (f.path().stem().string().rfind(stem, 0) == 0 && f.path() != ck)  // this method's files only
      CHECK_THAT(f.path().stem().string(), Contains(".tmp"));
  const Report resumed = solveReport(method, "--shots 48 --resume " + ck, "resumed");
  CHECK(resumed.json["method"] == method.name());
  CHECK(resumed.json["shots"] == 48);
  CHECK(resumed.hash() == whole.hash());
  CHECK(resumed.json["convergence_history"].dump() == whole.json["convergence_history"].dump());
}

TEST_CASE(
    "Every method solves a closed box of emitting grey walls to the B it declares, and one seed gives "
    "byte-identical images",
    "[heavy][gl][closed-box]") {
  const std::string name = GENERATE(from_range(methodNames()));
  const std::vector<std::unique_ptr<MethodUnit>> methods = makeMethods();
  const MethodUnit& method = named(methods, name);
  const ClosedBoxRun box = method.closedBox();
  REQUIRE(box.tolerance > 0);
  std::vector<std::string> images;
  for (const char* run : {"a", "b"}) {
    images.push_back(test::tempPath("closed-box-" + method.name() + "-" + run + ".exr"));
    const std::string args = "solve " + test::sourcePath("scenes/analytic/furnace.obj") + " --quiet --method " +
                             method.name() + " " + box.flags + " --out " + images.back();
    test::Run solved = test::hemirad(args);
    INFO(args << "\n" << solved.output);
    REQUIRE(solved.exitCode == 0);
  }
  const double mean = test::meanPixel(readImage(images[0]));
  INFO("--method " << method.name() << " " << box.flags << ": mean B " << mean << ", declared " << box.expected
                   << " within " << 100 * box.tolerance << " %");
  CHECK(std::abs(mean / box.expected - 1) <= box.tolerance);
  CHECK(test::readText(images[0]) == test::readText(images[1]));
}

namespace {

// A method of the test's own: it only emits (B = E), taking --shots and nothing else. What adding
// a method takes: this class and its line in the registry (here, the choice's list).
class NoTransport final : public Solver {
 public:
  explicit NoTransport(const StopRule& stop) : stop_(stop) {}
  std::string algorithm() const override { return "emit-only"; }
  SolveStatus advance(unsigned shots) override {
    status_.shots += stop_.maxShots ? std::min(shots, stop_.maxShots - status_.shots) : shots;
    status_.done = status_.shots >= stop_.maxShots;
    return status_;
  }
  const PassTimings& timings() const override { return timings_; }
  std::vector<float> convergenceHistory() const override { return std::vector<float>(status_.shots + 1, 0.0f); }
  std::vector<std::uint8_t> saveState() const override { return {}; }
  SolveStatus restoreState(std::span<const std::uint8_t>) override { return status_; }

 private:
  const StopRule& stop_;
  SolveStatus status_;
  PassTimings timings_;
};

class EmitOnlyRun final : public AtlasRun {
 public:
  explicit EmitOnlyRun(const StopRule& stop) : solver_(stop) {}
  Solver& solver() override { return solver_; }
  void look(const Camera&, double) override {}
  bool ambient() const override { return false; }
  void describe(RunInfo& run) const override { run.shootLevel = 0; }
  std::string reached(const SolveStatus& status) const override { return std::to_string(status.shots) + " shots"; }
  int walkthrough(const SolveOptions&, const Scene&, const Atlas&, SolverState&, const Camera&) override { return 1; }

 private:
  NoTransport solver_;
};

class EmitOnly final : public AtlasMethod {
 public:
  std::string name() const override { return "emit-only"; }
  std::vector<MethodFlag> flags() override { return {bindFlag("--shots", stop_.maxShots)}; }
  void settle(const SolveOptions&) override {
    if (!stop_.maxShots) throw InputError("--method emit-only needs --shots");
  }
  std::string quickFlags() const override { return "--elements 100"; }
  ClosedBoxRun closedBox() const override { return {"--shots 1", 1, 1e-6}; }  // B = E: nothing transported
  std::unique_ptr<AtlasRun> start(SolverState&) const override { return std::make_unique<EmitOnlyRun>(stop_); }
  nlohmann::json identity() const override { return {{"shots", stop_.maxShots}}; }
  const StopRule& stop() const override { return stop_; }

 private:
  StopRule stop_;
};

}  // namespace

TEST_CASE("A method added to the choice gets its flags bound, refuses the others' and runs as a Solver", "[gl]") {
  std::vector<std::unique_ptr<MethodUnit>> methods = makeMethods();
  auto added = std::make_unique<EmitOnly>();
  const EmitOnly& method = *added;
  methods.push_back(std::move(added));
  const MethodChoice choice(std::move(methods));
  CLI::App app;
  CLI::App* solve = app.add_subcommand("solve");
  choice.declareFlags(solve);
  app.parse("hemirad solve --shots 3", true);
  CHECK(&choice.choose("emit-only", *solve) == &method);
  CHECK(method.stop().maxShots == 3);
  CHECK(method.identity() == nlohmann::json{{"shots", 3}});
  CLI::App refusing;
  CLI::App* other = refusing.add_subcommand("solve");
  choice.declareFlags(other);
  refusing.parse("hemirad solve --shots 3 --converge 0.5", true);
  CHECK_THROWS_WITH(choice.choose("emit-only", *other), "--converge is for --method progressive, not emit-only");

  const Scene scene = test::cube(0.5, 0.0, 1);  // the ceiling a lamp (E 1, rho 0), the other five grey, dark
  test::backend();
  const Atlas atlas = buildAtlas(scene, 1.0 / 4);
  SolverState state(scene, atlas);
  const std::unique_ptr<AtlasRun> run = method.start(state);
  const SolveStatus status = advanceToStop(run->solver(), {});
  CHECK(status.shots == 3);
  const std::vector<ObjectRadiosity> objects = objectRadiosity(scene, atlas, state.readRadiosity());
  REQUIRE(objects.size() == 1);
  CHECK(objects[0].mean.x == Approx(1.0 / 6));  // the lamp's emission over the box, nothing transported
}

TEST_CASE(
    "The viewer and the bench pick methods by registered name: each runs only registered methods and the bench "
    "measures every one",
    "[cli]") {
  const std::vector<std::string> registered = methodNames();
  auto isRegistered = [&](const std::string& n) {
    return std::find(registered.begin(), registered.end(), n) != registered.end();
  };
  for (const std::string& name : viewerMethods()) CHECK(isRegistered(name));
  const std::vector<std::string> bench = benchMethods();
  CHECK(std::is_permutation(bench.begin(), bench.end(), registered.begin(), registered.end()));
  // A name the viewer has no worker for is refused by the flag, before any work.
  const test::Run refused = test::hemirad("view " + kScene + " --method stochastic");
  INFO(refused.output);
  CHECK(refused.exitCode == 2);
  CHECK(test::errorLines(refused.output) == 1);
  CHECK_THAT(refused.output, Contains("--method") && Contains("instant") && Contains("progressive"));
}
