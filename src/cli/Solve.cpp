#include "src/cli/Solve.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <tuple>

#include "src/base/AtomicFile.h"
#include "src/base/OutputPaths.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/solver/Checkpoint.h"
#include "src/base/Interrupt.h"
#include "src/base/Error.h"
#include "src/output/GltfWriter.h"
#include "src/output/ImageFile.h"
#include "src/output/PlyWriter.h"
#include "src/output/Progress.h"
#include "src/output/Renderer.h"
#include "src/output/Report.h"

namespace hemirad {

namespace {

Image atlasImage(const Atlas& atlas, const std::vector<glm::vec4>& B) {
  Image img{atlas.width, atlas.height, std::vector<float>(B.size() * 3)};
  for (size_t t = 0; t < B.size(); ++t)
    for (int c = 0; c < 3; ++c) img.rgb[t * 3 + c] = B[t][c];
  return img;
}

// What a checkpoint must have been made from to be resumed by this solve.
nlohmann::json checkpointIdentity(const Scene& scene, const Atlas& atlas, const SolveOptions& o, const Solver& solver) {
  const ProgressiveSettings& p = o.progressive;
  nlohmann::json identity = {{"scene_hash", fmt::format("{:016x}", sceneHash(scene))},
          {"algorithm", solver.algorithm()},
          {"texel_size", atlas.texelSize},
          {"atlas", {atlas.width, atlas.height}},
          {"elements", atlas.elements},
          {"item_subdivision", p.itemSubdivision},
          {"item_resolution", p.itemResolution},
          {"projection", projectionName(p.projection)},
          {"shoot_level", p.shootLevel},
          {"shooters_per_pass", p.shootersPerPass}};
  if (o.progressive.algorithm == Algorithm::Perspective) identity["fov_decay"] = p.fovDecayShots;  // 0: the default
  if (o.method == Method::Stochastic) {
    identity["seed"] = o.stochastic.seed;
    identity["transport"] = sourceName(o.stochastic.source);
  }
  return identity;
}

Checkpoint takeCheckpoint(const SolverState& state, const Solver& solver, const nlohmann::json& identity,
                          unsigned shots) {
  return {identity, shots, state.readRadiosity(), state.readDeltaB(), solver.saveState()};
}

int runWalkthrough(const SolveOptions& o, const Scene& scene, const Atlas& atlas, SolverState& state,
                   ProgressiveSolver& solver, const Camera& camera) {
  const CameraPath path = readCameraPath(o.cameraPath, camera, scene.unitScale);
  WalkthroughOptions w = o.walkthrough;
  w.width = o.width, w.height = o.height, w.supersample = o.supersample, w.ambient = o.ambient, w.exposure = o.exposure;
  w.writeFrame = writePng;
  w.progress = o.progress;
  ConvergedViews converged(scene, atlas, o.progressive, o.referenceConvergence, o.progress);
  const std::vector<FrameRecord> frames = walk(solver, state, path, converged, w);
  writeFramesCsv(w.framesDir + "/frames.csv", frames);
  const FrameRecord& last = frames.back();
  fmt::print(stderr, "hemirad: {}: {} frames along {} ({} shots, visible convergence {:.4f}, image error {:.4f}) into {}\n",
             o.scene, frames.size(), o.cameraPath, last.shots, last.visibleConvergence, last.imageError, w.framesDir);
  return 0;
}

// What only progressive refinement reports: the item mesh and seed 004's view-driven shots.
void describeProgressive(RunInfo& run, const ProgressiveSolver& solver) {
  run.importanceShots = solver.importanceShots();
  run.deliveryShots = solver.deliveryShots();
  run.fovDecayShots = solver.fovDecayShots();
  run.itemTriangles = solver.itemTriangles();
}

// Every file the solve will write, with its flag and the formats it takes.
std::vector<OutputPath> solveOutputs(const SolveOptions& o) {
  std::vector<OutputPath> outputs;
  auto add = [&](const std::string& path, const char* flag, std::vector<std::string> exts, bool stdoutOk = false) {
    if (!path.empty()) outputs.push_back({flag, path, std::move(exts), stdoutOk});
  };
  add(o.out, "--out", {".exr", ".png"});
  add(o.image, "--image", {".png"});
  add(o.atlas, "--atlas", {".exr"});
  add(o.ply, "--ply", {".ply"});
  add(o.report, "--report", {".json"}, true);
  add(o.checkpoint, "--checkpoint", {".ckpt"});
  if (!o.gltf.empty()) {
    const GltfPaths files = gltfPaths(o.gltf);
    add(files.glb, "--gltf", {".glb"});
    add(files.exr, "--gltf", {});
  }
  return outputs;
}

}  // namespace

void checkSolveOutputs(const SolveOptions& o, std::vector<InputPath> inputs) {
  std::vector<OutputPath> outputs = solveOutputs(o);
  std::error_code ec;  // --checkpoint run.ckpt --resume run.ckpt goes on where it stopped
  if (!o.resume.empty() && !(!o.checkpoint.empty() && std::filesystem::equivalent(o.checkpoint, o.resume, ec)))
    inputs.push_back({"the checkpoint resumed from (--resume)", o.resume});
  checkOutputs(outputs, inputs);
}

namespace {

// Everything checkable before a scene is read: the method, writable outputs, flag combinations.
void checkSolveInputs(const SolveOptions& o) {
  requireBuilt(o.method);
  checkSolveOutputs(o, {{"the scene", o.scene}});
  if (o.out.empty() && o.image.empty() && o.atlas.empty() && o.ply.empty() && o.gltf.empty() && o.report.empty() &&
      o.checkpoint.empty() && o.cameraPath.empty())
    warn("no output flag (--out, --image, --atlas, --ply, --gltf, --report, --checkpoint): only the summary line will "
         "show the result");
}

// Shots run in batches between status readbacks; a signal or a due checkpoint is handled
// between batches, where the GPU state is whole. Batch sizes never change the result. Returns
// 128 + the signal when one stopped the solve, else 0.
int solveInBatches(const SolveOptions& o, const SolverState& state, Solver& solver, const nlohmann::json& identity,
                   SolveStatus& status, Progress& progress) {
  InterruptGuard interrupts;
  unsigned savedAt = status.shots;
  for (unsigned batch = 1; !status.done;) {
    if (int signal = InterruptGuard::received()) {
      progress.finish();
      if (!o.checkpoint.empty()) writeCheckpoint(o.checkpoint, takeCheckpoint(state, solver, identity, status.shots));
      fmt::print(stderr, "hemirad: interrupted by {} after {} shots (convergence {:.4f}); {}\n", signalName(signal),
                 status.shots, status.convergence,
                 o.checkpoint.empty() ? "no --checkpoint given, nothing saved"
                                      : fmt::format("checkpoint written: resume with --resume {}", o.checkpoint));
      return 128 + signal;
    }
    auto t0 = std::chrono::steady_clock::now();
    status = solver.advance(o.checkpointEvery ? std::min(batch, o.checkpointEvery) : batch);
    progress.update(status);
    batch = nextBatch(batch, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (!o.checkpoint.empty() && o.checkpointEvery && status.shots >= savedAt + o.checkpointEvery && !status.done) {
      writeCheckpoint(o.checkpoint, takeCheckpoint(state, solver, identity, status.shots));
      savedAt = status.shots;
    }
  }
  progress.finish();
  if (!o.checkpoint.empty()) writeCheckpoint(o.checkpoint, takeCheckpoint(state, solver, identity, status.shots));
  return 0;
}

// The camera render (EXR, PNG), the atlas, the PLY and the glTF the user asked for, staged.
// Returns the lightmap's line for stderr, printed once the files are written ("" without --gltf).
std::string stageImages(OutputBatch& outputs, const SolveOptions& o, const Scene& scene, const Atlas& atlas,
                 const SolverState& state, const Camera& camera, const std::vector<glm::vec4>& B) {
  Image view;
  double scale = 1;
  if (!o.out.empty() || !o.image.empty() || !o.ply.empty() || !o.gltf.empty()) {
    Renderer renderer(state);
    // The ambient term stands in for light not yet shot (dB); stochastic iteration keeps its
    // iterate there instead, and its running mean already holds every bounce.
    renderer.setAmbient(o.ambient && o.method == Method::Progressive);
    view = renderer.render(camera, o.width, o.height, o.supersample);
    scale = exposureScale(view, o.exposure);
  }
  if (!o.out.empty()) outputs.add("--out", o.out, encodeRender(o.out, view, scale));
  if (!o.image.empty()) outputs.add("--image", o.image, encodePng(view, scale));
  if (!o.atlas.empty()) outputs.add("--atlas", o.atlas, encodeExr(atlasImage(atlas, B)));
  if (!o.ply.empty()) outputs.add("--ply", o.ply, encodePly(scene, atlas, B, scale));
  if (!o.gltf.empty()) {
    const GltfPaths files = gltfPaths(o.gltf);
    const GltfFiles gltf = encodeGltf(files, scene, atlas, B, camera, double(o.width) / o.height, scale);
    stageGltf(outputs, files, gltf);
    const Lightmap& map = gltf.map;
    return fmt::format("hemirad: {}: {} x {} lightmap, {} elements, texel use {:.1f} % (charts with {}-texel gutters "
                       "{:.1f} %){}\n",
                       o.gltf, map.width, map.height, map.elements, 100 * map.texelUse(), map.gutter,
                       100 * map.packing(),
                       files.exr.empty() ? " (a stream: no .lightmap.exr beside it)" : " and " + files.exr);
  }
  return "";
}

// The report's description of the run; the item buffer and shoot level are the ones the
// progressive solver used (planned ones with auto).
RunInfo describeRun(const SolveOptions& o, const gl::RenderBackend& backend, const Atlas& atlas, const Solver& solver) {
  RunInfo run;
  run.backend = backend.name();
  run.renderer = backend.renderer();
  run.method = methodName(o.method);
  run.algorithm = solver.algorithm();
  run.scene = o.scene;
  run.texelSize = atlas.texelSize;
  run.itemSubdivision = o.progressive.itemSubdivision;
  run.itemResolution = o.progressive.itemResolution;
  run.shootLevel = o.progressive.shootLevel;
  run.shootersPerPass = o.progressive.shootersPerPass;
  run.elements = atlas.elements;
  if (auto* progressive = dynamic_cast<const ProgressiveSolver*>(&solver)) {
    describeProgressive(run, *progressive);
    run.itemResolution = progressive->plan().itemResolution;
  }
  if (auto* stochastic = dynamic_cast<const StochasticSolver*>(&solver)) {
    run.itemResolution = stochastic->itemResolution();
    run.itemTriangles = stochastic->itemTriangles();
    run.shootLevel = 0;  // one-texel shooters
  }
  run.atlasWidth = atlas.width;
  run.atlasHeight = atlas.height;
  run.timings = solver.timings();
  run.convergenceHistory = solver.convergenceHistory();
  return run;
}

}  // namespace

int runSolve(const SolveOptions& o) {
  auto start = std::chrono::steady_clock::now();
  if (o.method == Method::Instant) return runInstantSolve(o);
  checkSolveInputs(o);
  std::optional<Checkpoint> resumed;
  if (!o.resume.empty()) resumed = readCheckpoint(o.resume);

  Scene scene = loadScene(o.scene, o.load);
  printWarnings(scene.warnings);
  checkSolveOutputs(o, scene.sources);
  validateSolvable(scene);
  Camera camera = resolveCamera(scene, o.camera);

  auto backend = gl::createBackend(o.backend);
  if (o.backend.kind == gl::BackendKind::Auto)
    fmt::print(stderr, "hemirad: backend auto chose {} ({})\n", backend->name(), backend->renderer());
  Atlas atlas = buildAtlas(scene, chooseTexelSize(scene, o.discretisation), backend->maxTextureSize());
  SolverState state(scene, atlas);
  const std::unique_ptr<Solver> method = makeSolver(o.method, state, o.progressive, o.stochastic);
  Solver& solver = *method;
  auto* progressive = dynamic_cast<ProgressiveSolver*>(method.get());  // view-driven shooting, walkthroughs
  const nlohmann::json identity = checkpointIdentity(scene, atlas, o, solver);
  SolveStatus status;
  if (resumed) {
    checkResumable(o.resume, resumed->identity, identity);
    state.restore(resumed->radiosity, resumed->deltaB);
    status = solver.restoreState(resumed->solver);
    resumed.reset();
  }
  if (!o.cameraPath.empty()) return runWalkthrough(o, scene, atlas, state, *progressive, camera);
  if (o.progressive.importanceDriven()) progressive->look(camera, double(o.width) / o.height);  // after a restore: no change

  Progress progress(o.progressive.stop, o.progress);
  if (int interrupted = solveInBatches(o, state, solver, identity, status, progress)) return interrupted;
  const double solveMs = progress.elapsedSeconds() * 1e3;
  const std::vector<glm::vec4> B = state.readRadiosity();
  OutputBatch outputs;  // all or none: a full disk on the last leaves none of the others
  const std::string lightmapLine = stageImages(outputs, o, scene, atlas, state, camera, B);

  RunInfo run = describeRun(o, *backend, atlas, solver);
  run.status = status;
  run.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  run.radiosityHash = radiosityHash(atlas, B);
  run.objects = objectRadiosity(scene, atlas, B);
  run.texelSize /= scene.unitScale;  // lengths and areas in the file's units
  for (ObjectRadiosity& ob : run.objects) ob.area /= scene.unitScale * scene.unitScale;
  if (!o.report.empty()) outputs.add("--report", o.report, reportJson(run).dump(2) + "\n");
  outputs.commit();
  fmt::print(stderr, "{}", lightmapLine);
  const std::string reached = o.method == Method::Stochastic
                                   ? fmt::format("{} iterations of {} shooters", status.shots, o.stochastic.shooters)
                                   : fmt::format("{} shots, convergence {:.4f}", status.shots, status.convergence);
  fmt::print(stderr, "hemirad: {}: {} elements, {} in {:.0f} ms ({}, {})\n", o.scene, atlas.elements, reached, solveMs,
             backend->name(), backend->renderer());
  return 0;
}

}  // namespace hemirad
