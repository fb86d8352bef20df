#include "src/bench/Bench.h"

#include <fmt/format.h>

#include <chrono>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>

#include "src/base/AtomicFile.h"
#include "src/scene/Camera.h"
#include "src/bench/Ceilings.h"
#include "src/base/Error.h"
#include "src/solver/Control.h"
#include "src/output/Report.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

namespace {

struct BenchRow {
  std::string scene;
  std::size_t elements = 0, itemTriangles = 0, itemPixels = 0;
  int shootersPerPass = 1;
  unsigned shots = 0;
  double convergence = 0, solveMs = 0, msPerShot = 0;
  PassTimings split;  // ms per shot, synchronised
  double itemTrianglesPerSecond = 0, itemPixelsPerSecond = 0, gatherUpdatesPerSecond = 0;
  std::uint64_t hash = 0;                // of the converged B: equal across runs on one backend
  std::vector<ObjectRadiosity> objects;  // for comparing backends (--compare)
};

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Runs to the stop rule; returns the wall time of the shots (setup excluded).
double runToStop(gl::RenderBackend& backend, ProgressiveSolver& solver, SolveStatus& status) {
  backend.finish();
  auto t0 = Clock::now();
  status = advanceToStop(solver, status);
  backend.finish();
  return msSince(t0);
}

BenchRow benchOne(gl::RenderBackend& backend, const Scene& scene, const Atlas& atlas, int shootersPerPass,
                  const BenchOptions& o) {
  BenchRow row;
  row.elements = atlas.elements;
  row.shootersPerPass = shootersPerPass;

  SolverState state(scene, atlas);
  ProgressiveSettings settings = o.progressive;
  settings.shootersPerPass = shootersPerPass;
  settings.stop = {0, o.converge};
  settings.timings = gl::TimerMode::Off;  // the timed run pays for no queries
  ProgressiveSolver solver(state, settings);
  // View-driven algorithms look from the scene's camera (SCENE.camera), square.
  const Camera camera = resolveCamera(scene, std::nullopt);
  if (solver.viewDriven()) solver.look(camera, 1.0);
  SolveStatus status;
  row.solveMs = runToStop(backend, solver, status);
  row.shots = status.shots;
  row.convergence = status.convergence;
  row.msPerShot = row.shots ? row.solveMs / row.shots : 0;
  row.itemTriangles = solver.itemTriangles();
  row.itemPixels = solver.itemPixels();
  std::vector<glm::vec4> B = state.readRadiosity();
  row.hash = radiosityHash(atlas, B);
  row.objects = objectRadiosity(scene, atlas, B);

  // The split: a fresh solve timed pass by pass (waits at every pass end), over the first shots
  // (at least 8 passes).
  SolverState fresh(scene, atlas);
  settings.timings = gl::TimerMode::Synchronous;
  settings.stop = {std::min(std::max(o.splitShots, 8u * shootersPerPass), std::max(row.shots, 1u)), 0};
  ProgressiveSolver timed(fresh, settings);
  if (timed.viewDriven()) timed.look(camera, 1.0);
  SolveStatus s2;
  runToStop(backend, timed, s2);
  const PassTimings& t = timed.timings();
  double n = std::max(1u, s2.shots);
  row.split = {t.itemBuffer / n, t.gather / n, t.select / n, t.readback / n};
  if (row.split.itemBuffer > 0) {
    row.itemTrianglesPerSecond = double(row.itemTriangles) / (row.split.itemBuffer * 1e-3);
    row.itemPixelsPerSecond = double(row.itemPixels) / (row.split.itemBuffer * 1e-3);
  }
  if (row.split.gather > 0) row.gatherUpdatesPerSecond = double(row.elements) / (row.split.gather * 1e-3);
  return row;
}

// Per-object relative differences of mean luminance between this run's rows and another bench
// JSON's rows of the same scene and element count (e.g. an NVIDIA run against llvmpipe).
std::string comparisonTable(const nlohmann::json& rows, const std::string& otherPath) {
  std::ifstream in(otherPath);
  if (!in) fail("--compare {}: cannot be read", otherPath);
  nlohmann::json other;
  try {
    other = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    fail("--compare {}: not a bench JSON: {}", otherPath, e.what());
  }
  std::string out = fmt::format("\nagainst {} ({}): per-object relative difference of mean luminance\n\n", otherPath,
             other.value("renderer", "?"));
  out += "| scene | elements | shooters/pass | object | this | other | relative difference |\n|---|---|---|---|---|---|---|\n";
  auto lum = [](const nlohmann::json& c) { return 0.2126 * double(c[0]) + 0.7152 * double(c[1]) + 0.0722 * double(c[2]); };
  for (const auto& a : rows)
    for (const auto& b : other.value("rows", nlohmann::json::array())) {
      if (a["scene"] != b["scene"] || a["elements"] != b["elements"] || !b.contains("objects") ||
          a["shooters_per_pass"] != b.value("shooters_per_pass", 1))
        continue;
      for (const auto& oa : a["objects"])
        for (const auto& ob : b["objects"]) {
          if (oa["name"] != ob["name"]) continue;
          double x = lum(oa["mean_radiosity"]), y = lum(ob["mean_radiosity"]);
          out += fmt::format("| {} | {} | {} | {} | {:.6g} | {:.6g} | {:.2e} |\n", a["scene"].get<std::string>(),
                     a["elements"].get<std::size_t>(), a["shooters_per_pass"].get<int>(), oa["name"].get<std::string>(), x, y,
                     y != 0 ? std::abs(x - y) / std::abs(y) : std::abs(x - y));
        }
    }
  return out;
}

}  // namespace

void addBenchFlags(CLI::App* cmd, BenchOptions& o) {
  cmd->add_option("--scenes", o.scenes, "OBJ scenes (default scenes/cornell/cornell.obj)")->delimiter(',');
  cmd->add_option("--elements", o.elements, "Element counts to generate each scene at (default 10000,100000)")
      ->delimiter(',')
      ->check(CLI::Range(std::size_t(1), std::size_t(1) << 28));
  cmd->add_option("--converge", o.converge, "Convergence to time (default 0.9)")->check(CLI::Range(1e-6, 0.999999));
  cmd->add_option("--shoot-level", o.progressive.shootLevel, "Substructuring level (default 1)")->check(CLI::Range(0, 8));
  cmd->add_option("--item-subdiv", o.progressive.itemSubdivision, "Item-mesh level L (default 3)")->check(CLI::Range(0, 8));
  cmd->add_option("--item-res", o.progressive.itemResolution, "Item buffer resolution (default 512)")
      ->check(CLI::Range(16, 16384));
  cmd->add_option("--shooters-per-pass", o.shootersPerPass,
                  fmt::format("Shooters per pass, one row each (default 16; at most {})", kMaxPassShooters))
      ->delimiter(',')
      ->check(CLI::Range(1, int(kMaxPassShooters)));
  cmd->add_option_function<std::string>(
         "--algorithm", [&o](const std::string& a) { o.progressive.algorithm = parseAlgorithm(a); },
         "progressive (default), importance or perspective (view-driven ones look from SCENE.camera)")
      ->check(CLI::IsMember(algorithmNames()));
  cmd->add_option("--markdown", o.markdown, "Write the printed tables as markdown (e.g. into docs/bench)");
  cmd->add_option("--split-shots", o.splitShots, "Shots timed pass by pass for the split (default 64)")
      ->check(CLI::Range(1u, 1u << 20));
  cmd->add_option("--backend", o.backendName, "GL backend: osmesa (default), egl, auto")
      ->check(CLI::IsMember({"osmesa", "egl", "auto"}));
  cmd->add_option("--gpu", o.backend.gpu, "EGL device index")->check(CLI::NonNegativeNumber);
  cmd->add_option("--json", o.json, "Write the results as JSON");
  cmd->add_option("--compare", o.compare, "Another bench JSON: print per-object differences to its matching rows");
  cmd->add_flag("--ceiling", o.ceiling,
                "Also measure the device's ceilings (load-store invocations/s, item-buffer triangles/s) and "
                "print each throughput as a fraction of them");
}

namespace {

// Per-shot throughputs: item-buffer triangles and pixels (the shot's whole buffer; overdraw
// makes the fragments more) and gather texel updates, per second of their pass.
std::string tableHeader(const BenchOptions& o) {
  return fmt::format("| scene | elements | shooters/pass | shots | time to {:.0f}% (ms) | ms/shot | item buffer ms | gather ms | "
                     "select ms | item tris/s | item px/s | gather texels/s |{}\n|---|---|---|---|---|---|---|---|---|---|---|---|{}\n",
                     o.converge * 100, o.ceiling ? " tris / ceiling | px / fill ceiling | gather / ceiling |" : "",
                     o.ceiling ? "---|---|---|" : "");
}

// A row of the table, with the fractions of the ceilings when they were measured.
std::string rowMarkdown(const BenchRow& r, const Ceilings* ceiling) {
  std::string fractions =
      ceiling ? fmt::format(" {:.1f} % | {:.1f} % | {:.1f} % |", 100 * r.itemTrianglesPerSecond / ceiling->trianglesPerSecond,
                            100 * r.itemPixelsPerSecond / ceiling->fragmentsPerSecond,
                            100 * r.gatherUpdatesPerSecond / ceiling->invocationsPerSecond)
              : "";
  return fmt::format("| {} | {} | {} | {} | {:.1f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.3g} | {:.3g} | {:.3g} |{}\n",
                     r.scene, r.elements, r.shootersPerPass, r.shots, r.solveMs, r.msPerShot, r.split.itemBuffer,
                     r.split.gather, r.split.select, r.itemTrianglesPerSecond, r.itemPixelsPerSecond,
                     r.gatherUpdatesPerSecond, fractions);
}

nlohmann::json rowJson(const BenchRow& r) {
  return {{"scene", r.scene}, {"elements", r.elements}, {"shooters_per_pass", r.shootersPerPass},
          {"shots", r.shots}, {"convergence", r.convergence}, {"time_to_converge_ms", r.solveMs},
          {"ms_per_shot", r.msPerShot},
          {"split_ms_per_shot", {{"item_buffer", r.split.itemBuffer}, {"gather", r.split.gather},
                                 {"select", r.split.select}, {"readback", r.split.readback}}},
          {"item_triangles", r.itemTriangles}, {"item_triangles_per_s", r.itemTrianglesPerSecond},
          {"item_pixels", r.itemPixels}, {"item_pixels_per_s", r.itemPixelsPerSecond},
          {"gather_texel_updates_per_s", r.gatherUpdatesPerSecond},
          {"radiosity_hash", fmt::format("{:016x}", r.hash)}, {"objects", objectsJson(r.objects)}};
}

}  // namespace

int runBench(BenchOptions o) {
  if (!o.json.empty()) checkWritable(o.json, "--json");
  if (!o.markdown.empty()) checkWritable(o.markdown, "--markdown");
  o.backend.kind = gl::parseBackendKind(o.backendName);
  auto backend = gl::createBackend(o.backend);
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::string text;  // everything printed, for --markdown
  auto say = [&text](const std::string& s) {
    fmt::print("{}", s);
    std::fflush(stdout);
    text += s;
  };
  say(fmt::format("hemirad bench, {}, {} ({}), {}, converge {}, shoot level {}, item mesh L{}, item buffer {}^2\n\n",
                  date, backend->name(), backend->renderer(), algorithmName(o.progressive.algorithm), o.converge,
                  o.progressive.shootLevel,
                  o.progressive.itemSubdivision, o.progressive.itemResolution));
  Ceilings ceiling;
  if (o.ceiling) {
    ceiling = measureCeilings(*backend, o.scenes.front());
    say(fmt::format("ceilings: {:.3g} load-store invocations/s, {:.3g} item-buffer triangles/s (first scene, item "
                    "mesh L6), {:.3g} item-buffer fragments/s (fill)\n\n",
                    ceiling.invocationsPerSecond, ceiling.trianglesPerSecond, ceiling.fragmentsPerSecond));
  }
  say(tableHeader(o));
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& path : o.scenes) {
    Scene scene = loadScene(path);
    validateSolvable(scene);
    for (std::size_t n : o.elements) {
      Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, n), backend->maxTextureSize());
      for (int k : o.shootersPerPass) {
        BenchRow r = benchOne(*backend, scene, atlas, k, o);
        r.scene = path;
        say(rowMarkdown(r, o.ceiling ? &ceiling : nullptr));
        rows.push_back(rowJson(r));
      }
    }
  }
  if (!o.compare.empty()) say(comparisonTable(rows, o.compare));
  if (!o.json.empty()) {
    nlohmann::json out = {{"date", date},
                          {"backend", backend->name()},
                          {"renderer", backend->renderer()},
                          {"algorithm", algorithmName(o.progressive.algorithm)},
                          {"converge", o.converge},
                          {"shoot_level", o.progressive.shootLevel},
                          {"item_subdivision", o.progressive.itemSubdivision},
                          {"item_resolution", o.progressive.itemResolution},
                          {"rows", rows}};
    if (o.ceiling)
      out["ceilings"] = {{"load_store_invocations_per_s", ceiling.invocationsPerSecond},
                         {"item_buffer_triangles_per_s", ceiling.trianglesPerSecond},
                         {"item_buffer_fragments_per_s", ceiling.fragmentsPerSecond}};
    writeTextFile(o.json, out.dump(2) + "\n");
  }
  if (!o.markdown.empty()) writeTextFile(o.markdown, "# " + text);
  return 0;
}

}  // namespace hemirad
