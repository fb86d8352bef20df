// Parameter sweeps (docs/sweeps.md) without Slurm: the job-array script a spec makes; tasks run
// one by one as Slurm would run them, one stopped by SIGTERM mid-solve and run again, merge to
// the bytes of a local `--jobs 2` run; merge lists missing and failed configurations; bad specs
// are refused before anything is written. tests/slurm/sweep.sh runs the same on a real Slurm.
#include <algorithm>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "src/base/Error.h"
#include "src/cli/SweepCommand.h"
#include "src/sweep/SweepSpec.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Matchers::Contains;
namespace fs = std::filesystem;

namespace {

using test::readText;

// Cornell box, 300 elements, 4 configurations (item-mesh level x item-buffer resolution) of
// 96 shots each: a second or so apiece on llvmpipe, checkpointed every 16 shots. Seed 003's
// orthographic item buffer, whose item-mesh level changes the result (the default hemicube is
// exact at every level).
std::string cornellSpec(const std::string& name) {
  return test::writeTempFile(name, R"({
  "name": "cornell-item-mesh",
  "scenes": [")" + test::sourcePath("scenes/cornell/cornell.obj") +
                                       R"("],
  "axes": {"item-subdiv": [0, 2], "item-res": [64, 128]},
  "flags": {"elements": 300, "shots": 96, "shooters-per-pass": 4, "preset": "seed003"},
  "resources": {"cpus": 2, "mem": "1G", "time": "00:05:00"},
  "checkpoint_every": 16,
  "metrics": ["shots", "convergence", "radiosity_hash", "objects.floor.mean_radiosity"],
  "plot": {"x": "item-res", "y": "convergence"}
})");
}

// The local run's merged table and figure, computed once.
const std::pair<std::string, std::string>& localResults() {
  static const std::pair<std::string, std::string> results = [] {
    const std::string dir = test::tempPath("sweep-local");
    test::Run run = test::hemirad("experiment " + cornellSpec("local.json") + " --out-dir " + dir + " --jobs 2");
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return std::pair{readText(dir + "/results.csv"), readText(dir + "/results.svg")};
  }();
  return results;
}

}  // namespace

TEST_CASE(
    "A sweep's tasks run as Slurm runs them (one stopped by SIGTERM mid-solve and run again) merge to the bytes "
    "of a local --jobs 2 run",
    "[heavy][cli][sweep]") {
  const std::string dir = test::tempPath("sweep-tasks");
  test::Run made = test::hemirad("experiment " + cornellSpec("tasks.json") + " --slurm " + dir);
  INFO(made.output);
  REQUIRE(made.exitCode == 0);
  const std::string script = readText(dir + "/sweep.sbatch");
  CHECK_THAT(script, Contains("#SBATCH --array=0-3\n") && Contains("#SBATCH --cpus-per-task=2\n") &&
                         Contains("#SBATCH --mem=1G\n") && Contains("#SBATCH --time=00:05:00\n") &&
                         Contains("#SBATCH --requeue\n") && Contains("#SBATCH --signal=B:USR1@60\n") &&
                         Contains("experiment run-task " + dir + " \"$SLURM_ARRAY_TASK_ID\""));
  CHECK_THAT(script, !Contains("--gres"));
  // Task 1 is stopped once its first checkpoint (16 shots) is written, then run again: the
  // requeue. The others run whole, beside it, logging where Slurm would.
  const std::string ck = dir + "/tasks/0001/checkpoint.ckpt";
  test::Run run = test::shell("for i in 0 2 3; do $HEMIRAD experiment run-task " + dir + " $i >>" + dir +
                              "/logs/task_$i.log 2>&1 || echo \"task $i failed\" & done\n"
                              "$HEMIRAD experiment run-task " +
                              dir +
                              " 1 & p=$!\n"
                              "while [ ! -e " +
                              ck +
                              " ] && kill -0 $p 2>/dev/null; do sleep 0.01; done\n"
                              "kill -TERM $p; wait $p; echo \"first attempt exit $?\"; wait\n"
                              "$HEMIRAD experiment merge " +
                              dir +
                              "; echo \"merge exit $?\"\n"
                              "$HEMIRAD experiment run-task " +
                              dir +
                              " 1; echo \"second attempt exit $?\"\n"
                              "$HEMIRAD experiment run-task " +
                              dir + " 1; echo \"third attempt exit $?\"");
  INFO(run.output);
  CHECK_THAT(run.output, Contains("first attempt exit 143") && Contains("interrupted by SIGTERM"));
  CHECK_THAT(run.output,
             Contains("merge exit 1") && Contains("configuration 0001 (") && Contains("missing (checkpointed)"));
  CHECK_THAT(run.output, Contains("task 0001 (scene=") && Contains("resuming from its checkpoint at"));
  CHECK_THAT(run.output,
             Contains("second attempt exit 0") && Contains("already done") && Contains("third attempt exit 0"));
  CHECK_THAT(run.output, !Contains("failed"));
  test::Run merged = test::hemirad("experiment merge " + dir);
  INFO(merged.output);
  REQUIRE(merged.exitCode == 0);
  const std::string table = readText(dir + "/results.csv");
  CHECK(table == localResults().first);
  const std::string figure = readText(dir + "/results.svg");
  CHECK(figure == localResults().second);
  // matplotlib's SVG: a legend entry per line (item-subdiv 0 and 2), convergence against item-res,
  // and the sweep as its provenance.
  // (Text is drawn as glyph outlines; matplotlib keeps each string in a comment beside them.)
  CHECK(test::count(figure, "<!-- scene=cornell, item-subdiv=") == 2);
  CHECK_THAT(figure,
             Contains("<!-- scene=cornell, item-subdiv=0 -->") && Contains("<!-- scene=cornell, item-subdiv=2 -->"));
  CHECK_THAT(figure, Contains("<dc:description>hemirad ") && Contains("sweep cornell-item-mesh (4 configurations"));
  CHECK(readText(dir + "/results.pdf").rfind("%PDF-", 0) == 0);
  CHECK(test::count(table, ",done\n") == 4);
  CHECK_THAT(table, Contains("id,scene,item-subdiv,item-res,shots,convergence,radiosity_hash,"
                             "objects.floor.mean_radiosity,status\n"));
  // Every row solved its own configuration: 96 shots each, and four different solutions.
  std::set<std::string> hashes;
  std::istringstream rows(table);
  std::string line;
  std::getline(rows, line);  // the header
  while (std::getline(rows, line)) {
    CHECK_THAT(line, Contains(",96,"));
    std::vector<std::string> cells;
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() == 9);
    hashes.insert(cells[6]);  // radiosity_hash
  }
  CHECK(hashes.size() == 4);
}

TEST_CASE("merge lists missing and failed configurations with their error lines and tabulates only complete ones",
          "[heavy][cli][sweep]") {
  const std::string folder = test::tempPath("sweep-fail");
  fs::create_directories(folder);
  const std::string dark = test::writeScene(folder, "mtllib m.mtl\nusemtl grey\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                                            "newmtl grey\nKd 0.5 0.5 0.5\n", "dark.obj");
  const std::string spec = test::writeTempFile("fail.json", R"({
  "scenes": [")" + test::sourcePath("scenes/cornell/cornell.obj") +
                                                                R"(", ")" + dark + R"("],
  "axes": {"method": ["progressive", "stochastic"]},
  "flags": {"elements": 100, "shots": 8, "item-res": 32},
  "metrics": ["shots", "radiosity_hash"]
})");
  const std::string dir = test::tempPath("sweep-fail-dir");
  REQUIRE(test::hemirad("experiment " + spec + " --slurm " + dir).exitCode == 0);
  test::Run failedTask = test::hemirad("experiment run-task " + dir + " 2");  // dark, progressive
  INFO(failedTask.output);
  CHECK(failedTask.exitCode == 2);
  const std::string errorLine = readText(dir + "/tasks/0002/error");
  CHECK_THAT(errorLine, Contains("hemirad: error:") && Contains("emit"));
  REQUIRE(test::hemirad("experiment run-task " + dir + " 0").exitCode == 0);
  test::Run merged = test::hemirad("experiment merge " + dir);
  INFO(merged.output);
  CHECK(merged.exitCode == 1);
  CHECK_THAT(merged.output, Contains("1 of 4 configurations done"));
  CHECK_THAT(merged.output, Contains("configuration 0001 (") && Contains("stochastic): missing"));
  CHECK_THAT(merged.output, Contains("configuration 0002 (" + dark +
                                     ", progressive): failed: " + errorLine.substr(0, errorLine.size() - 1)));
  const std::string table = readText(dir + "/results.csv");
  CHECK(test::count(table, ",done\n") == 1);
  CHECK(test::count(table, ",,,missing\n") == 2);
  CHECK(test::count(table, ",,,failed\n") == 1);
  test::Run again = test::hemirad("experiment run-task " + dir + " 4");
  CHECK(again.exitCode == 2);
  CHECK_THAT(again.output, Contains("the index must be 0 to 3"));
}

TEST_CASE("A bad sweep spec is refused with one error line before anything is written", "[cli][sweep][bad-input]") {
  const std::string scene = test::sourcePath("scenes/cornell/cornell.obj");
  const std::string scenes = R"("scenes": [")" + scene + R"("], )";
  // Through the binary: the error line, the exit code, no folder.
  auto refused = [&](const std::string& body, const std::string& why, const std::string& flags = "") {
    const std::string spec = test::writeTempFile("bad.json", body);
    const std::string dir = test::tempPath("sweep-bad");
    test::Run run = test::hemirad("experiment " + spec + (flags.empty() ? " --slurm " + dir : flags));
    INFO(run.output);
    CHECK(run.exitCode == 2);
    CHECK(test::errorLines(run.output) == 1);
    CHECK_THAT(run.output, Contains(why));
    CHECK(!fs::exists(dir));
  };
  refused("{" + scenes + R"("axes": {"item-subdivs": [0, 1]}, "metrics": ["shots"]})", "did you mean --item-subdiv?");
  refused("{" + scenes + R"("metrics": ["shots"]})", "--jobs is for a local run",
          " --jobs 2 --slurm " + test::tempPath("sweep-bad"));
  // The same reading and checks in-process: the message of each refusal.
  auto message = [&](const std::string& body) {
    try {
      readSweepSpec(test::writeTempFile("bad-spec.json", body), checkHemiradArgs);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK_THAT(message("{" + scenes + R"("axes": {"item-subdiv": [0, 9]}, "metrics": ["shots"]})"),
             Contains("configuration 0001 (" + scene + ", 9)") && Contains("--item-subdiv"));
  CHECK_THAT(message("{" + scenes + R"("flags": {"report": "r.json"}, "metrics": ["shots"]})"),
             Contains("--report is set by each task"));
  CHECK_THAT(message("{" + scenes + R"("flags": {"method": "stochastic"}, "metrics": ["shots"]})"),
             Contains("--method stochastic needs --shots"));
  CHECK_THAT(message("{" + scenes + R"("metrics": ["shot"]})"),
             Contains("metric 'shot': 'shot' is not a report field"));
  CHECK_THAT(message("{" + scenes + R"("metrics": ["shots"], "resource": {}})"), Contains("unknown field 'resource'"));
  CHECK_THAT(message("{" + scenes + R"("metrics": ["shots"], "resources": {"gpu": "yes"}})"),
             Contains("resources.gpu"));
  CHECK_THAT(message("{" + scenes + R"("metrics": ["shots"], "resources": {"mem": "1 G"}})"),
             Contains("'1 G' is not a Slurm value"));
  CHECK_THAT(message(R"({"scenes": ["missing.obj"], "metrics": ["shots"]})"), Contains("missing.obj"));
  CHECK_THAT(message("{" + scenes + R"("axes": {"shots": []}, "metrics": ["shots"]})"),
             Contains("axes.shots must be a non-empty list"));
  CHECK_THAT(message("{" + scenes + R"("metrics": ["shots"], "plot": {"x": "item-res", "y": "shots"}})"),
             Contains("plot.x 'item-res' is not one of the axes"));
  CHECK_THAT(message("not json"), Contains("not valid JSON"));
  CHECK(message("{" + scenes + R"("axes": {"item-subdiv": [0, 1]}, "metrics": ["shots"]})") == "accepted");
}

TEST_CASE("A GPU sweep's array tasks request a GPU with --gres and solve on EGL", "[cli][sweep]") {
  const std::string spec = test::writeTempFile("gpu.json", R"({
  "scenes": [")" + test::sourcePath("scenes/cornell/cornell.obj") +
                                                               R"("],
  "axes": {"item-res": [256, 512, 1024]},
  "resources": {"gpu": true, "cpus": 4, "mem": "8G", "time": "02:00:00"},
  "metrics": ["shots", "timings_ms.total"]
})");
  const std::string dir = test::tempPath("sweep-gpu");
  test::Run run = test::hemirad("experiment " + spec + " --slurm " + dir);
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  const std::string script = readText(dir + "/sweep.sbatch");
  CHECK_THAT(script, Contains("#SBATCH --array=0-2\n") && Contains("#SBATCH --gres=gpu:1\n") &&
                         Contains("#SBATCH --cpus-per-task=4\n") && Contains("#SBATCH --job-name=hemirad-gpu\n"));
  const nlohmann::json sweep = test::readJson(dir + "/sweep.json");
  REQUIRE(sweep["configurations"].size() == 3);
  const std::vector<std::string> egl = {"--backend", "egl"};
  for (const auto& c : sweep["configurations"]) {
    const auto args = c["args"].get<std::vector<std::string>>();
    CHECK(std::search(args.begin(), args.end(), egl.begin(), egl.end()) != args.end());
  }
  CHECK(sweep["configurations"][2]["values"] ==
        nlohmann::json({test::sourcePath("scenes/cornell/cornell.obj"), "1024"}));
}
