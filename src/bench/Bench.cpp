#include "src/bench/Bench.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>

#include "gl/StoragePool.h"
#include "src/base/AtomicFile.h"
#include "src/base/Clock.h"
#include "src/base/DataDir.h"
#include "src/base/Error.h"
#include "src/base/ResidentMemory.h"
#include "src/bench/Ceilings.h"
#include "src/bench/InstantBench.h"
#include "src/bench/SceneSize.h"
#include "src/bench/StochasticBench.h"
#include "src/options/Options.h"
#include "src/output/Progress.h"
#include "src/output/Provenance.h"
#include "src/output/Report.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Control.h"

namespace hemirad {

namespace {

struct BenchRow {
  std::string scene;
  SceneSize size;       // polygons and triangles
  double texelUse = 0;  // elements / atlas texels
  std::size_t elements = 0, itemTriangles = 0, itemPixels = 0, shooterBlocks = 0;
  int itemResolution = 0;
  std::string visibility;              // as the solver resolved --visibility
  std::optional<double> gpuMemoryMiB;  // what the solve holds on the device, where the driver says
  std::size_t allocatedBytes = 0;      // the most the solve's buffers and textures held (gl::allocatedBytes)
  std::size_t residentBytes = 0;       // the process's resident peak after the row (VmHWM)
  int shootersPerPass = 1;
  unsigned shots = 0;
  double convergence = 0, solveMs = 0, msPerShot = 0;
  double warmUpMs = 0;  // the untimed passes before the timed run (warmUp)
  // Of solveMs, the time the CPU waited for the GPU at status readbacks (the only sync): near all
  // of it, the GPU bounds the solve; near none, the CPU's submission of the passes does.
  double waitMs = 0;
  PassTimings split;  // ms per shot
  double busy = 0;    // the split's ms per shot x shots / solveMs
  double itemTrianglesPerSecond = 0, itemPixelsPerSecond = 0, gatherUpdatesPerSecond = 0;
  std::uint64_t hash = 0;                // of the converged B: equal across runs on one backend
  std::vector<ObjectRadiosity> objects;  // for comparing backends (--compare)
};

// Runs to the stop rule; returns the wall time of the shots (setup excluded). Given the stop rule,
// shows the bar (or a line every few seconds) after each batch: a row can take many minutes.
double runToStop(gl::RenderBackend& backend, ProgressiveSolver& solver, SolveStatus& status,
                 const StopRule* progress = nullptr) {
  backend.finish();
  Progress bar(progress ? *progress : StopRule{}, progress != nullptr);
  auto t0 = Clock::now();
  status = advanceToStop(solver, status, [&](const SolveStatus& s) { bar.update(s); });
  backend.finish();
  bar.finish();
  return msSince(t0);
}

// Untimed passes first, until they run at a steady pace: drivers compile shaders and page buffers
// in at their first use, and a GPU left idle while the CPU built the row's atlas has clocked down
// (H200: 1,980 to 345 MHz within 3 s of idling, and up to ~1.2 s back up under load, in steps; a
// 1M-element row started there took 3x as long, docs/bench/h200-2026-12-04b.md). So chunks of
// passes of at least kChunkMs each run until one's time a shot is within kSteady of the one before,
// after at least kWarmUpMs on a hardware GPU (a CPU rasterizer has no clocks to ramp) and at most
// kWarmUpMaxMs.
constexpr double kChunkMs = 50, kSteady = 0.05, kWarmUpMs = 1500, kWarmUpMaxMs = 4000;

double warmUp(gl::RenderBackend& backend, const Scene& scene, const Atlas& atlas, ProgressiveSettings settings,
              const Camera& camera) {
  const auto t0 = Clock::now();
  const double least = backend.software() ? 0 : kWarmUpMs;
  settings.stop = {};  // no stop rule: passes until the pace is steady
  const unsigned batch = 4 * unsigned(settings.shootersPerPass);
  double last = 0, pace = 0;  // ms a shot of the chunk before and of the last one
  auto warming = [&] {
    const double ms = msSince(t0);
    return ms < kWarmUpMaxMs && (ms < least || last == 0 || std::abs(pace - last) > kSteady * last);
  };
  while (warming()) {  // a fresh solve whenever one runs out of light
    SolverState state(scene, atlas);
    ProgressiveSolver solver(state, settings);
    if (solver.viewDriven()) solver.look(camera, 1.0);
    SolveStatus status;
    while (!status.done && warming()) {
      backend.finish();
      const auto c0 = Clock::now();
      unsigned shots = 0;
      for (; !status.done && (shots == 0 || msSince(c0) < kChunkMs); shots += batch) status = solver.advance(batch);
      backend.finish();
      last = pace, pace = msSince(c0) / shots;
    }
  }
  return msSince(t0);
}

BenchRow benchOne(gl::RenderBackend& backend, const Scene& scene, const Atlas& atlas, int shootersPerPass,
                  const BenchOptions& o) {
  BenchRow row;
  row.elements = atlas.elements;
  row.shootersPerPass = shootersPerPass;

  ProgressiveSettings settings = o.progressive;
  settings.shootersPerPass = shootersPerPass;
  settings.stop = {0, o.converge};
  settings.timings = gl::TimerMode::Off;  // the timed run pays for no queries
  // View-driven algorithms look from the scene's camera (SCENE.camera), square.
  const Camera camera = resolveCamera(scene, std::nullopt);
  // The timed solve takes the storage the warm-up's solvers handed back (gl/StoragePool.h), paged
  // in: so the device's free memory is read before the warm-up, with no idle storage held.
  gl::dropIdleStorage();
  backend.finish();
  const std::optional<double> freeBefore = backend.freeMemoryMiB();
  row.warmUpMs = warmUp(backend, scene, atlas, settings, camera);
  backend.finish();
  const std::size_t allocatedBefore = gl::allocatedBytes();
  gl::resetPeakAllocatedBytes();
  SolverState state(scene, atlas);
  ProgressiveSolver solver(state, settings);
  if (solver.viewDriven()) solver.look(camera, 1.0);
  SolveStatus status;
  row.solveMs = runToStop(backend, solver, status, &settings.stop);
  if (const std::optional<double> freeAfter = backend.freeMemoryMiB(); freeBefore && freeAfter)
    row.gpuMemoryMiB = *freeBefore - *freeAfter;
  row.allocatedBytes = gl::peakAllocatedBytes() - allocatedBefore;
  row.size = sceneSize(scene);
  if (const std::optional<ResidentMemory> m = residentMemory()) row.residentBytes = m->peakBytes;
  row.shots = status.shots;
  row.convergence = status.convergence;
  row.msPerShot = row.shots ? row.solveMs / row.shots : 0;
  row.waitMs = solver.timings().readback;
  row.itemTriangles = solver.itemTriangles();
  row.itemPixels = solver.itemPixels();
  row.shooterBlocks = solver.shooterBlocks();
  row.itemResolution = solver.plan().itemResolution;
  row.visibility = visibilityName(solver.visibility());
  std::vector<glm::vec4> B = state.readRadiosity();
  row.hash = radiosityHash(atlas, B);
  row.objects = objectRadiosity(scene, atlas, B);

  // The split: a fresh solve timed stage by stage in every pass over the first shots (at least 8
  // passes), by GPU stamps (waiting at every stage would add a round trip to each; a CPU
  // rasterizer waits instead, gl::contextTimerMode).
  SolverState fresh(scene, atlas);
  settings.timings = gl::TimerMode::GpuEveryPass;
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
  // How much of the timed run the passes' own work fills; the rest the GPU waited (status
  // readbacks, the CPU's submission of the passes after each).
  if (row.solveMs > 0)
    row.busy = (row.split.select + row.split.itemBuffer + row.split.gather) * double(row.shots) / row.solveMs;
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
  out +=
      "| scene | elements | shooters/pass | object | this | other | relative difference "
      "|\n|---|---|---|---|---|---|---|\n";
  auto lum = [](const nlohmann::json& c) { return luminance(glm::dvec3(double(c[0]), double(c[1]), double(c[2]))); };
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
                             a["elements"].get<std::size_t>(), a["shooters_per_pass"].get<int>(),
                             oa["name"].get<std::string>(), x, y,
                             y != 0 ? std::abs(x - y) / std::abs(y) : std::abs(x - y));
        }
    }
  return out;
}

}  // namespace

void addBenchFlags(CLI::App* cmd, BenchOptions& o) {
  using options::add;
  add(cmd, "--scenes", o.scenes);
  add(cmd, "--elements", o.elements);
  add(cmd, "--chart-angle", o.chartAngle);
  add(cmd, "--converge", o.converge);
  options::addItemPlan(cmd, o.progressive);  // --preset, --hemisphere, --item-subdiv, --item-res, --shoot-level
  add(cmd, "--shooters-per-pass", o.shootersPerPass);
  add(cmd, "--algorithm", o.progressive.algorithm);
  add(cmd, "--method", o.method)->transform(options::oneOfNames(benchMethods()));
  add(cmd, "--atlas-sides", o.atlasSides);
  add(cmd, "--shots", o.iterations, "8 (--method stochastic: iterations timed per row; instant: frames)");
  add(cmd, "--markdown", o.markdown);
  add(cmd, "--split-shots", o.splitShots);
  add(cmd, "--backend", o.backend.kind);
  add(cmd, "--gpu", o.backend.gpu);
  add(cmd, "--json", o.json);
  add(cmd, "--compare", o.compare);
  options::addSwitch(cmd, "--ceiling", o.ceiling);
  add(cmd, "--vpls", o.vpls, "128,256,512 (--method instant: a row each)");
  add(cmd, "--vpl-bounces", o.instant.bounces);
  add(cmd, "--vpl-clamp", o.instant.clamp);
  add(cmd, "--shadow-res", o.instant.shadowResolution);
  add(cmd, "--seed", o.instant.seed);
  add(cmd, "--interleave", o.interleave, "1,4 (--method instant: a row each)");
  add(cmd, "--width", o.width, "1024 (--method instant: frame size)");
  add(cmd, "--height", o.height, "1024 (--method instant: frame size)");
}

namespace {

// Per-shot throughputs: item-buffer triangles and pixels (the shot's whole buffer; overdraw
// makes the fragments more) and gather texel updates, per second of their pass.
std::string tableHeader(const BenchOptions& o) {
  return fmt::format(
      "| scene | polygons | triangles | elements | texel use | shooter blocks | item res (bvh: traced) | shooters/pass "
      "| shots | "
      "time to {:.0f}% (ms) | ms/shot | GPU MiB | GPU alloc MiB (B/element, B/triangle) | resident MiB "
      "(B/element, B/triangle) | item buffer ms | gather ms | select ms | busy | item tris/s | item px/s | gather "
      "texels/s |{}\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|{}\n",
      o.converge * 100, o.ceiling ? " tris / ceiling | px / fill ceiling | gather / ceiling |" : "",
      o.ceiling ? "---|---|---|" : "");
}

// A row of the table, with the fractions of the ceilings when they were measured.
std::string rowMarkdown(const BenchRow& r, const Ceilings* ceiling) {
  std::string fractions = ceiling ? fmt::format(" {:.1f} % | {:.1f} % | {:.1f} % |",
                                                100 * r.itemTrianglesPerSecond / ceiling->trianglesPerSecond,
                                                100 * r.itemPixelsPerSecond / ceiling->fragmentsPerSecond,
                                                100 * r.gatherUpdatesPerSecond / ceiling->invocationsPerSecond)
                                  : "";
  const std::string memory = r.gpuMemoryMiB ? fmt::format("{:.0f}", *r.gpuMemoryMiB) : "n/a";
  const auto perUnit = [&r](std::size_t bytes) {
    return fmt::format("{:.1f} ({:.0f}, {:.0f})", bytes / 1048576.0,
                       double(bytes) / double(std::max<std::size_t>(r.elements, 1)),
                       double(bytes) / double(std::max<std::size_t>(r.size.triangles, 1)));
  };
  return fmt::format(
      "| {} | {} | {} | {} | {:.1f} % | {} | {} | {} | {} | {:.1f} | {:.4f} | {} | {} | {} | {:.4f} | {:.4f} | {:.4f} "
      "| {:.0f} % | {:.3g} | {:.3g} | {:.3g} |{}\n",
      r.scene, r.size.polygons, r.size.triangles, r.elements, 100 * r.texelUse, r.shooterBlocks,
      r.visibility == "bvh" ? std::string("bvh") : std::to_string(r.itemResolution), r.shootersPerPass, r.shots,
      r.solveMs, r.msPerShot, memory, perUnit(r.allocatedBytes), perUnit(r.residentBytes), r.split.itemBuffer,
      r.split.gather, r.split.select, 100 * r.busy, r.itemTrianglesPerSecond, r.itemPixelsPerSecond,
      r.gatherUpdatesPerSecond, fractions);
}

nlohmann::json rowJson(const BenchRow& r) {
  return {{"scene", r.scene},
          {"polygons", r.size.polygons},
          {"triangles", r.size.triangles},
          {"texel_use", r.texelUse},
          {"elements", r.elements},
          {"shooter_blocks", r.shooterBlocks},
          {"item_resolution", r.itemResolution},
          {"visibility", r.visibility},
          {"shooters_per_pass", r.shootersPerPass},
          {"shots", r.shots},
          {"convergence", r.convergence},
          {"time_to_converge_ms", r.solveMs},
          {"warm_up_ms", r.warmUpMs},
          {"gpu_wait_ms", r.waitMs},
          {"busy_fraction", r.busy},
          {"ms_per_shot", r.msPerShot},
          {"gpu_memory_mib", r.gpuMemoryMiB ? nlohmann::json(*r.gpuMemoryMiB) : nlohmann::json()},
          {"gpu_allocated_bytes", r.allocatedBytes},
          {"resident_peak_bytes", r.residentBytes},
          {"gpu_allocated_bytes_per_element", double(r.allocatedBytes) / double(std::max<std::size_t>(r.elements, 1))},
          {"gpu_allocated_bytes_per_triangle",
           double(r.allocatedBytes) / double(std::max<std::size_t>(r.size.triangles, 1))},
          {"resident_peak_bytes_per_element", double(r.residentBytes) / double(std::max<std::size_t>(r.elements, 1))},
          {"resident_peak_bytes_per_triangle",
           double(r.residentBytes) / double(std::max<std::size_t>(r.size.triangles, 1))},
          {"split_ms_per_shot",
           {{"item_buffer", r.split.itemBuffer},
            {"gather", r.split.gather},
            {"select", r.split.select},
            {"readback", r.split.readback}}},
          {"item_triangles", r.itemTriangles},
          {"item_triangles_per_s", r.itemTrianglesPerSecond},
          {"item_pixels", r.itemPixels},
          {"item_pixels_per_s", r.itemPixelsPerSecond},
          {"gather_texel_updates_per_s", r.gatherUpdatesPerSecond},
          {"radiosity_hash", fmt::format("{:016x}", r.hash)},
          {"objects", objectsJson(r.objects)}};
}

// Prints a piece of the bench's output (and keeps it for --markdown).
using Say = std::function<void(const std::string&)>;

// The stochastic method's rows and JSON (src/bench/StochasticBench.h).
void runStochasticBench(const BenchOptions& o, gl::RenderBackend& backend, const char* date, const Say& say) {
  say(fmt::format("hemirad bench, {}, {} ({}), stochastic iteration, preset {}: item mesh L{}, {} item buffer {}\n\n",
                  date, backend.name(), backend.renderer(), o.progressive.presetLabel(), o.progressive.itemSubdivision,
                  projectionName(o.progressive.projection),
                  settingText(o.progressive.itemResolution, kAutoItemResolution, "^2")));
  const nlohmann::json rows = benchStochastic(backend, o, say);
  if (!o.json.empty())
    writeTextFile(o.json, nlohmann::json{{"date", date},
                                         {"backend", backend.name()},
                                         {"renderer", backend.renderer()},
                                         {"method", "stochastic"},
                                         {"chart_angle", o.chartAngle},
                                         {"preset", o.progressive.presetLabel()},
                                         {"projection", projectionName(o.progressive.projection)},
                                         {"item_subdivision", o.progressive.itemSubdivision},
                                         {"item_resolution", o.progressive.itemResolution},
                                         {"rows", rows},
                                         {"provenance", provenanceJson(provenance(backend.name(), backend.renderer()))}}
                                  .dump(2) +
                              "\n");
}

}  // namespace

// Frames per second of instant radiosity per VPL count and interleave (seed 002's Figure 5 beside).
void runInstantBench(const BenchOptions& o, gl::RenderBackend& backend, const char* date, const Say& say) {
  say(fmt::format("hemirad bench, {}, {} ({}), instant radiosity (seed 002)\n\n", date, backend.name(),
                  backend.renderer()));
  const nlohmann::json rows = benchInstant(backend, o, say);
  if (!o.json.empty())
    writeTextFile(o.json, nlohmann::json{{"date", date},
                                         {"backend", backend.name()},
                                         {"renderer", backend.renderer()},
                                         {"method", "instant"},
                                         {"width", o.width},
                                         {"height", o.height},
                                         {"frames_per_row", o.iterations},
                                         {"shadow_resolution", o.instant.shadowResolution},
                                         {"rows", rows},
                                         {"provenance", provenanceJson(provenance(backend.name(), backend.renderer()))}}
                                  .dump(2) +
                              "\n");
}

// Time to convergence per scene, element count and shooters a pass, against the measured ceilings.
void runProgressiveBench(const BenchOptions& o, gl::RenderBackend& backend, const char* date, const Say& say) {
  const double refineNear = refineNearFor(o.progressive.refineNear, o.converge, false);  // what the solves run with
  say(
      fmt::format("hemirad bench, {}, {} ({}), {}, converge {}, chart angle {}, preset {}: shoot level {}, item mesh "
                  "L{}, {} item buffer {}, visibility {}, refine near {:g}\n\n",
                  date, backend.name(), backend.renderer(), algorithmName(o.progressive.algorithm), o.converge,
                  o.chartAngle, o.progressive.presetLabel(), settingText(o.progressive.shootLevel, kAutoShootLevel),
                  o.progressive.itemSubdivision, projectionName(o.progressive.projection),
                  settingText(o.progressive.itemResolution, kAutoItemResolution, "^2"),
                  visibilityName(o.progressive.visibility), refineNear));
  Ceilings ceiling;
  if (o.ceiling) {
    ceiling = measureCeilings(backend, o.scenes.front());
    say(fmt::format(
        "ceilings: {:.3g} load-store invocations/s, {:.3g} item-buffer triangles/s (first scene, item "
        "mesh L{}), {:.3g} item-buffer fragments/s (fill)\n\n",
        ceiling.invocationsPerSecond, ceiling.trianglesPerSecond, ceiling.triangleLevel, ceiling.fragmentsPerSecond));
  }
  say(tableHeader(o));
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& path : o.scenes) {
    Scene scene = loadScene(path);
    validateSolvable(scene);
    for (std::size_t n : o.elements) {
      Atlas atlas = buildAtlas(scene, Discretisation{.texelSize = {}, .elements = n, .chartAngle = o.chartAngle},
                               backend.maxTextureSize());
      for (int k : o.shootersPerPass) {
        BenchRow r = benchOne(backend, scene, atlas, k, o);
        r.scene = path;
        r.texelUse = texelUse(atlas);
        say(rowMarkdown(r, o.ceiling ? &ceiling : nullptr));
        rows.push_back(rowJson(r));
      }
    }
  }
  if (!o.compare.empty()) say(comparisonTable(rows, o.compare));
  if (!o.json.empty()) {
    nlohmann::json out = {{"date", date},
                          {"backend", backend.name()},
                          {"renderer", backend.renderer()},
                          {"algorithm", algorithmName(o.progressive.algorithm)},
                          {"converge", o.converge},
                          {"chart_angle", o.chartAngle},
                          {"preset", o.progressive.presetLabel()},
                          {"shoot_level", o.progressive.shootLevel},
                          {"item_subdivision", o.progressive.itemSubdivision},
                          {"item_resolution", o.progressive.itemResolution},
                          {"projection", projectionName(o.progressive.projection)},
                          {"visibility", visibilityName(o.progressive.visibility)},
                          {"refine_near", refineNear},
                          {"rows", rows},
                          {"provenance", provenanceJson(provenance(backend.name(), backend.renderer()))}};
    if (o.ceiling)
      out["ceilings"] = {{"load_store_invocations_per_s", ceiling.invocationsPerSecond},
                         {"item_buffer_triangles_per_s", ceiling.trianglesPerSecond},
                         {"item_mesh_level", ceiling.triangleLevel},
                         {"item_buffer_fragments_per_s", ceiling.fragmentsPerSecond}};
    writeTextFile(o.json, out.dump(2) + "\n");
  }
}

namespace {

using BenchRun = void (*)(const BenchOptions&, gl::RenderBackend&, const char*, const Say&);

// The bench's run of each method it measures, by --method name (tested to cover the registry).
const std::map<std::string, BenchRun>& benchRuns() {
  static const std::map<std::string, BenchRun> runs{
      {"progressive", runProgressiveBench}, {"stochastic", runStochasticBench}, {"instant", runInstantBench}};
  return runs;
}

}  // namespace

std::vector<std::string> benchMethods() {
  std::vector<std::string> names;
  for (const auto& [name, run] : benchRuns()) names.push_back(name);
  return names;
}

int runBench(BenchOptions o) {
  if (!o.json.empty()) checkWritable(o.json, "--json");
  if (!o.markdown.empty()) checkWritable(o.markdown, "--markdown");
  o.progressive.projection = options::oneProjection(int(o.progressive.projection));  // refuses `all`
  for (std::string& s : o.scenes) s = findScene(s);  // the shipped scenes from any directory
  auto backend = gl::createBackend(o.backend);
  std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  std::string text;  // everything printed, for --markdown
  const Say say = [&text](const std::string& s) {
    fmt::print("{}", s);
    std::fflush(stdout);
    text += s;
  };
  benchRuns().at(o.method)(o, *backend, date, say);
  if (!o.markdown.empty()) writeTextFile(o.markdown, "# " + text);
  return 0;
}

}  // namespace hemirad
