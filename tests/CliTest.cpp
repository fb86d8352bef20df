// The command line: bad input gets one `hemirad: error:` line and exit code 2, and leaves no
// output behind; runs are deterministic whatever llvmpipe's thread count.
#include <fmt/format.h>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {
std::string scene(const std::string& name) { return test::sourcePath("scenes/analytic/" + name); }

// Expects exit code 2, exactly one error line containing `message`, and no file at `output`.
void expectInputError(const std::string& args, const std::string& message, const std::string& output = "") {
  test::Run run = test::hemirad(args);
  INFO("hemirad " << args << "\n" << run.output);
  CHECK(run.exitCode == 2);
  CHECK(test::errorLines(run.output) == 1);
  CHECK_THAT(run.output, Contains(message));
  if (!output.empty()) CHECK_FALSE(std::filesystem::exists(output));
}
}  // namespace

TEST_CASE("Bad flags and bad scenes exit with code 2 and one error line, writing nothing", "[cli]") {
  std::string out = test::tempPath("never.exr");
  const std::string good = scene("parallel_squares.obj");
  expectInputError("solve /no/such.obj --out " + out, "such.obj", out);
  expectInputError("solve " + good + " --converge 1.5 --out " + out, "--converge", out);
  expectInputError("solve " + good + " --shots 0 --out " + out, "--shots", out);
  expectInputError("solve " + good + " --item-subdiv 99 --out " + out, "--item-subdiv", out);
  expectInputError("solve " + good + " --texel-size -1 --out " + out, "--texel-size", out);
  expectInputError("solve " + good + " --texel-size 0.1 --elements 10 --out " + out, "excludes", out);
  expectInputError("solve " + good + " --backend vulkan --out " + out, "--backend", out);
  expectInputError("solve " + good + " --camera eye=1,2 --out " + out, "--camera: 'eye' needs three numbers", out);
  expectInputError("solve " + good + " --out /no/such/folder/x.exr", "--out /no/such/folder/x.exr");
  expectInputError("frobnicate", "subcommand");

  const std::string mtl = "newmtl lamp\nKe 1 1 1\nnewmtl grey\nKd 0.5 0.5 0.5\n";
  const std::string quad = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  expectInputError(
      "solve " + test::writeScene("nomtl", "mtllib x.mtl\n" + quad.substr(13) + "f 1 2 3\n", mtl) + " --out " + out,
      "material library 'x.mtl' not found", out);
  expectInputError("solve " + test::writeScene("unknown", quad + "usemtl neon\nf 1 2 3\n", mtl) + " --out " + out,
                   ":6: unknown material 'neon'", out);
  expectInputError(
      "solve " + test::writeScene("nan", quad + "v nan 0 0\nusemtl lamp\nf 1 2 5\n", mtl) + " --out " + out,
      ":6: vertex coordinate is not a finite number", out);
  expectInputError("solve " + test::writeScene("dark", quad + "usemtl grey\nf 1 2 3 4\n", mtl) + " --out " + out,
                   "no emitter", out);
  expectInputError(
      "solve " + test::writeScene("bright", quad + "usemtl grey\nf 1 2 3 4\n", "newmtl grey\nKd 1.2 0 0\nKe 1 1 1\n") +
          " --out " + out,
      "reflectance Kd 1.2 is above 1", out);
  expectInputError("solve " + test::writeScene("empty", "", mtl) + " --out " + out, "no faces", out);
}

TEST_CASE("Degenerate faces are skipped with a warning and the solve goes on", "[cli]") {
  std::string obj = test::writeScene(
      "degenerate", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nusemtl lamp\nf 1 2 3 4\nf 1 2 5\n",
      "newmtl lamp\nKe 1 1 1\n");
  test::Run run = test::hemirad("solve " + obj + " --shots 3 --quiet");
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK_THAT(run.output, Contains("s.obj:9: degenerate face with zero area skipped"));
}

// A 20 cm lamp over 40 separate 5 cm squares; `materials` of them (round robin) for the squares.
std::string smallPartsScene(int materials) {
  std::string obj = "mtllib m.mtl\nv 0.4 2 0.4\nv 0.4 2 0.6\nv 0.6 2 0.6\nv 0.6 2 0.4\nusemtl lamp\nf 1 4 3 2\n";
  std::string mtl = "newmtl lamp\nKe 1 1 1\n";
  for (int m = 0; m < materials; ++m) mtl += fmt::format("newmtl grey{}\nKd 0.5 0.5 0.5\n", m);
  for (int k = 0; k < 40; ++k) {
    const double x = 0.1 * (k % 8), z = 0.2 * (k / 8);
    obj += fmt::format("usemtl grey{}\nv {} 0 {}\nv {} 0 {}\nv {} 0 {}\nv {} 0 {}\nf {} {} {} {}\n", k % materials, x,
                       z, x, z + 0.05, x + 0.05, z + 0.05, x + 0.05, z, 5 + 4 * k, 6 + 4 * k, 7 + 4 * k, 8 + 4 * k);
  }
  return test::writeScene(fmt::format("small_parts_{}", materials), obj, mtl);
}

TEST_CASE(
    "Small separate parts of one material share elements, so --elements 10 gives about 10, and of forty materials they "
    "cannot, and info warns with the count it could not go below",
    "[cli]") {
  test::Run clustered = test::hemirad("info " + smallPartsScene(1) + " --elements 10");
  INFO(clustered.output);
  CHECK(clustered.exitCode == 0);
  CHECK_THAT(clustered.output, !Contains("charts holds at least one"));
  const std::size_t at = clustered.output.find("elements     ");
  REQUIRE(at != std::string::npos);
  const int elements = std::stoi(clustered.output.substr(at + 13));
  CHECK(elements >= 8);
  CHECK(elements <= 12);
  test::Run apart = test::hemirad("info " + smallPartsScene(40) + " --elements 10");
  INFO(apart.output);
  CHECK(apart.exitCode == 0);
  CHECK_THAT(apart.output, Contains("41 elements for --elements 10: each of the 41 charts holds at least one"));
  CHECK_THAT(test::hemirad("info " + smallPartsScene(40) + " --elements 400").output,
             !Contains("charts holds at least one"));
}

TEST_CASE("Help lists the solve flags", "[cli]") {
  test::Run run = test::hemirad("solve --help");
  CHECK(run.exitCode == 0);
  for (const char* flag : {"--converge", "--shots", "--item-subdiv", "--item-res", "--texel-size", "--camera",
                           "--shoot-level", "--report", "--ply", "--atlas", "--image", "--out", "--emission"})
    CHECK_THAT(run.output, Contains(flag));
}

TEST_CASE("Determinism guard: B after a fixed number of shots hashes the same across runs and llvmpipe thread counts",
          "[heavy][cli]") {
  // Every solver path: the default (the fast preset, 16 shooters a pass), one shooter a pass, seed
  // 003's orthographic item buffer, importance-driven.
  auto hashOf = [](const std::string& flags, const std::string& env) {
    std::string report = test::tempPath("det" + std::to_string(std::hash<std::string>{}(flags + env)) + ".json");
    test::Run run =
        test::hemirad("solve " + test::sourcePath("scenes/cornell/cornell.obj") +
                          " --elements 1500 --shots 64 --item-res 256 --quiet " + flags + " --report " + report,
                      env);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return test::readJson(report)["radiosity_hash"].get<std::string>();
  };
  std::string a = hashOf("", ""), b = hashOf("", ""), one = hashOf("", "LP_NUM_THREADS=1"),
              three = hashOf("", "LP_NUM_THREADS=3");
  CHECK(a == b);
  CHECK(a == one);
  CHECK(a == three);
  for (const char* flags : {"--shooters-per-pass 1", "--preset seed003", "--algorithm importance"}) {
    INFO(flags);
    std::string x = hashOf(flags, ""), single = hashOf(flags, "LP_NUM_THREADS=1");
    CHECK(x != a);  // a different path, so a different (but reproducible) result
    CHECK(x == single);
  }
}

TEST_CASE(
    "The orthographic map's old name, --hemisphere stereographic, gives its bitwise result with a warning, and "
    "conformal and equal-area give others",
    "[heavy][cli]") {
  auto solve = [](const std::string& flags) {
    std::string report = test::tempPath("proj" + std::to_string(std::hash<std::string>{}(flags)) + ".json");
    // Seed 003's item buffer at 128^2 and item-mesh level 0, where each map bends the mesh's straight
    // edges its own way and so nominates other occluders (at L3 two maps may nominate the same).
    test::Run run =
        test::hemirad("solve " + test::sourcePath("scenes/cornell/cornell.obj") +
                      " --elements 1500 --shots 32 --preset seed003 --item-res 128 --item-subdiv 0 --quiet " + flags +
                      " --report " + report);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return std::pair{test::readJson(report)["radiosity_hash"].get<std::string>(), run.output};
  };
  const auto [orthographic, quiet] = solve("");
  const auto [old, warned] = solve("--hemisphere stereographic");
  CHECK(old == orthographic);
  CHECK(solve("--hemisphere hemisphere").first == orthographic);
  CHECK_THAT(warned, Contains("hemirad: warning: --hemisphere stereographic is seed 003's orthographic"));
  CHECK_THAT(quiet, !Contains("warning"));
  const std::string conformal = solve("--hemisphere conformal").first;
  CHECK(conformal != orthographic);
  CHECK(solve("--hemisphere paraboloid").first == conformal);
  CHECK(solve("--hemisphere equal-area").first != orthographic);
}

TEST_CASE("OSMesa and EGL on llvmpipe give bitwise-identical radiosity", "[heavy][cli]") {
  auto run = [](const std::string& backend) {
    std::string report = test::tempPath("backend-" + backend + ".json");
    test::Run r = test::hemirad("solve " + test::sourcePath("scenes/cornell/cornell.obj") +
                                " --elements 3000 --shots 100 --quiet --backend " + backend + " --report " + report);
    INFO(r.output);
    REQUIRE(r.exitCode == 0);
    return test::readJson(report);
  };
  nlohmann::json osmesa = run("osmesa"), egl = run("egl");
  CHECK(osmesa["backend"] == "osmesa");
  CHECK(egl["backend"] == "egl");
  CHECK(osmesa["radiosity_hash"] == egl["radiosity_hash"]);
}

namespace {
// The command lines of a doc's ```sh blocks (continuations joined) and `inline` spans that start
// with `prefix`, with the prefix cut off: what a user would paste.
std::vector<std::string> documentedCommands(const std::string& doc, const std::string& prefix) {
  std::ifstream in(test::sourcePath(doc));
  std::vector<std::string> out;
  std::string line, joined;
  bool block = false;
  while (std::getline(in, line)) {
    if (line.starts_with("```")) block = !block && line.size() > 3;
    for (std::size_t at = 0; !block && (at = line.find("`" + prefix, at)) != std::string::npos; ++at)
      out.push_back(line.substr(at + 1 + prefix.size(), line.find('`', at + 1) - at - 1 - prefix.size()));
    if (!block) continue;
    joined += line.substr(0, line.find(" #"));
    if (!joined.empty() && joined.back() == '\\') {
      joined.pop_back();
      continue;
    }
    if (joined.starts_with(prefix)) out.push_back(joined.substr(prefix.size()));
    joined.clear();
  }
  return out;
}
}  // namespace

TEST_CASE("The README's and docs/gpu.md's commands parse as written in both binaries, space-separated values too",
          "[heavy][cli]") {
  std::vector<std::pair<std::string, std::string>> commands;  // binary, arguments
  for (const std::string& args : documentedCommands("README.md", "build/hemirad "))
    commands.emplace_back("\"$HEMIRAD\"", args);
  for (const std::string& args : documentedCommands("docs/gpu.md", ".gpu/run "))  // hemirad-bench on the GPU machine
    if (args.find('[') == std::string::npos) commands.emplace_back("\"$(dirname \"$HEMIRAD\")/hemirad-bench\"", args);
  REQUIRE(commands.size() >= 8);
  // The space form of a value list, which hemirad-bench once took for a subcommand's name.
  commands.emplace_back("\"$(dirname \"$HEMIRAD\")/hemirad-bench\"", "--elements 10000 --shooters-per-pass 1,16");
  commands.emplace_back("\"$HEMIRAD\"", "bench --elements 10000 --shooters-per-pass 1,16");
  for (const auto& [binary, args] : commands) {
    // --help after the flags: the flags are checked (names, subcommand), then the help ends the run.
    test::Run run = test::shell("cd " + test::sourcePath(".") + " && " + binary + " " + args + " --help");
    INFO(binary << " " << args << "\n" << run.output);
    CHECK(run.exitCode == 0);
    CHECK(run.output.find("hemirad: error") == std::string::npos);
  }
}
