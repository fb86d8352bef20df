#include "src/cli/Solve.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <optional>
#include <tuple>

#include "gl/Limits.h"
#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/base/Interrupt.h"
#include "src/base/OutputPaths.h"
#include "src/cli/AdaptiveRounds.h"
#include "src/output/DirectLight.h"
#include "src/output/GltfWriter.h"
#include "src/output/ImageFile.h"
#include "src/output/NearGather.h"
#include "src/output/PlyWriter.h"
#include "src/output/Progress.h"
#include "src/output/Renderer.h"
#include "src/output/Report.h"
#include "src/output/ShownRadiosity.h"
#include "src/output/Smoothness.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/ContactCuts.h"
#include "src/solver/Checkpoint.h"
#include "src/solver/DirectSplit.h"

namespace hemirad {

namespace {

Image atlasImage(const Atlas& atlas, const std::vector<glm::vec4>& B) {
  Image img{atlas.width, atlas.height, std::vector<float>(B.size() * 3)};
  for (size_t t = 0; t < B.size(); ++t)
    for (int c = 0; c < 3; ++c) img.rgb[t * 3 + c] = B[t][c];
  return img;
}

// What a checkpoint must have been made from to be resumed by this solve: the scene, the atlas
// and the method's parameters.
nlohmann::json checkpointIdentity(const Scene& scene, const Atlas& atlas, const AtlasMethod& method,
                                  const Solver& solver) {
  nlohmann::json identity = method.identity();
  identity.update({{"scene_hash", fmt::format("{:016x}", sceneHash(scene))},
                   {"algorithm", solver.algorithm()},
                   {"texel_size", atlas.texelSize},
                   {"atlas", {atlas.width, atlas.height}},
                   {"atlas_layout", fmt::format("{:016x}", atlas.layoutHash())},
                   {"elements", atlas.elements}});
  return identity;
}

Checkpoint takeCheckpoint(const SolverState& state, const Solver& solver, const nlohmann::json& identity,
                          unsigned shots) {
  return {identity, shots, state.readRadiosity(), state.readDeltaB(), solver.saveState()};
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
  checkSolveOutputs(o, {{"the scene", o.scene}});
  if (o.subdivide.adaptive && o.discretisation.uv == UvSource::Input)  // leaves split projection charts only
    throw InputError("--subdivide adaptive splits projection charts; it cannot take --uv input's charts");
  if (o.discontinuities && o.discretisation.uv == UvSource::Input)  // contact cuts split projection charts only
    throw InputError("--discontinuities contact cuts projection charts; it cannot take --uv input's charts");
  if (o.out.empty() && o.image.empty() && o.atlas.empty() && o.ply.empty() && o.gltf.empty() && o.report.empty() &&
      o.checkpoint.empty() && o.cameraPath.empty())
    warn(
        "no output flag (--out, --image, --atlas, --ply, --gltf, --report, --checkpoint): only the summary line will "
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

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The camera view: B looked up in the atlas, or with `--direct per-pixel` (only when --out or
// --image is asked for) E + each pixel's exact direct light + the indirect part of B
// (src/solver/DirectSplit.h, src/output/DirectLight.h), timed into `run`.
Image cameraView(const SolveOptions& o, const Scene& scene, const Atlas& atlas, const SolverState& state,
                 const AtlasRun& method, const Camera& camera, const std::vector<glm::vec4>& solved,
                 const ShownRadiosity& shownOf, const std::vector<glm::vec4>& shown, RunInfo& run) {
  Renderer renderer(state);
  renderer.setAmbient(o.ambient.value_or(false) && method.ambient());
  renderer.setMultisample(std::min(o.msaa.value_or(SolveOptions::kDefaultMsaa), gl::limits().cameraSamples));
  auto t0 = std::chrono::steady_clock::now();
  const bool image = !o.out.empty() || !o.image.empty();
  const std::vector<glm::vec4> direct =
      image ? method.directOnly(camera, double(o.width) / o.height) : std::vector<glm::vec4>{};
  run.supersample = o.supersample;
  if (direct.empty()) {
    renderer.show(shown);
    Image view = renderer.render(camera, o.width, o.height, o.supersample);
    run.msaa = renderer.lastSamples();
    return view;
  }
  renderer.show(shownOf(indirectPart(solved, direct)));
  const DirectLight light(scene, state.farDistance);
  std::optional<NearGather> gather;
  if (method.nearGather()) gather.emplace(scene, atlas, sentOn(scene, atlas, solved));
  renderer.usePerPixelDirect(light, gather ? &*gather : nullptr);
  run.directSplitMs = msSince(t0);
  t0 = std::chrono::steady_clock::now();
  Image view = renderer.render(camera, o.width, o.height, o.supersample);
  run.directPixelsMs = msSince(t0);
  run.msaa = renderer.lastSamples();
  run.gatherShares = gather ? renderer.lastShares().gather : 0;
  run.directShares = renderer.lastShares().direct;
  return view;
}

// The camera render (EXR, PNG), the atlas, the PLY and the glTF the user asked for, staged.
// Returns the lightmap's line for stderr, printed once the files are written ("" without --gltf).
std::string stageImages(OutputBatch& outputs, const SolveOptions& o, const Scene& scene, const Atlas& atlas,
                        const SolverState& state, const AtlasRun& run, const Camera& camera,
                        const std::vector<glm::vec4>& solved, RunInfo& info) {
  Image view;
  double scale = 1;
  const std::vector<SmoothEdge> edges = smoothEdges(scene);  // the seams' and the report's
  const ShownRadiosity shownOf(scene, atlas, edges);         // buried texels filled, seams stitched
  const std::vector<glm::vec4> B = shownOf(solved);
  if (!o.report.empty()) {
    info.smoothness = measureSmoothness(scene, atlas, edges, B);
    info.seamJumpUnstitched = measureSmoothness(scene, atlas, edges, solved).seamJump;
  }
  if (!o.out.empty() || !o.image.empty() || !o.ply.empty() || !o.gltf.empty()) {
    view = cameraView(o, scene, atlas, state, run, camera, solved, shownOf, B, info);
    scale = exposureScale(view, o.exposure);
  }
  if (!o.out.empty()) outputs.add("--out", o.out, encodeRender(o.out, view, scale));
  if (!o.image.empty()) outputs.add("--image", o.image, encodePng(view, scale));
  if (!o.atlas.empty()) outputs.add("--atlas", o.atlas, encodeExr(atlasImage(atlas, solved)));  // the elements' own
  if (!o.ply.empty()) outputs.add("--ply", o.ply, encodePly(scene, atlas, B, scale));
  if (!o.gltf.empty()) {
    const GltfPaths files = gltfPaths(o.gltf);
    const GltfFiles gltf = encodeGltf(files, scene, atlas, B, camera, double(o.width) / o.height, scale);
    stageGltf(outputs, files, gltf);
    const Lightmap& map = gltf.map;
    return fmt::format("hemirad: {}: {} x {} lightmap, {} elements, texel use {:.1f} % (charts{} {:.1f} %){}\n", o.gltf,
                       map.width, map.height, map.elements, 100 * map.texelUse(), gutterWords(map.gutter),
                       100 * map.packing(),
                       files.exr.empty() ? " (a stream: no .lightmap.exr beside it)" : " and " + files.exr);
  }
  return "";
}

// --discontinuities contact: the scene and its atlas cut along the D0 lines (src/scene/ContactCuts.h).
void cutAtContacts(Scene& scene, Atlas& atlas, int maxTextureSize, double chartAngle) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<ContactLine> lines = findContacts(scene, atlas, contactDistance(scene));
  const double findMs = msSince(t0);
  std::optional<ContactLayout> cut = cutAlongContacts(scene, atlas, lines);
  const double cutMs = msSince(t0) - findMs;
  if (!cut) {
    fmt::print(stderr, "hemirad: discontinuities: {} contact lines found in {:.0f} ms; none cuts a chart\n",
               lines.size(), findMs);
    return;
  }
  const std::size_t before = atlas.elements;
  atlas = buildAtlas(cut->scene, cut->specs, atlas.texelSize, maxTextureSize, 0, chartAngle);
  scene = std::move(cut->scene);
  fmt::print(
      stderr,
      "hemirad: discontinuities: {} contact lines found in {:.0f} ms; {} of them cut {} charts into {} pieces in "
      "{:.0f} ms: {} elements, {} uncut\n",
      lines.size(), findMs, cut->lines, cut->charts, cut->pieces, cutMs, atlas.elements, before);
}

// A converged solve's image plan, on stderr: exact (with what is in effect of it), or quick where
// auto keeps a CPU's time.
void announceImagePlan(const SolveOptions& o, const AtlasMethod& method) {
  const double targetConvergence = method.stop().targetConvergence;
  std::vector<std::string> parts = method.pixelRefinements();
  if (o.discontinuities) parts.emplace_back("contact cuts");
  parts.push_back(fmt::format("{} x {} samples a pixel", o.supersample, o.supersample));
  if (method.exactImages())
    fmt::print(stderr, "hemirad: the camera image is exact (--image-plan {}): {} (docs/solve.md#exact-images)\n",
               o.imagePlan == ImagePlan::Exact ? "exact" : "auto", fmt::join(parts, ", "));
  else if (o.imagePlan == ImagePlan::Auto && exactImagesFor(o.imagePlan, targetConvergence, o.cameraImage(), true))
    fmt::print(stderr,
               "hemirad: converging to {:g} on a CPU rasterizer: the quick camera image; --image-plan exact for the "
               "exact one, 10-100x the time here (docs/solve.md#exact-images)\n",
               targetConvergence);
}

// The report's description of the run: what every atlas method has, then the method's own.
RunInfo describeRun(const SolveOptions& o, const gl::RenderBackend& backend, const Atlas& atlas, AtlasRun& method) {
  RunInfo run;
  run.backend = backend.name();
  run.renderer = backend.renderer();
  run.method = o.method->name();
  run.algorithm = method.solver().algorithm();
  run.scene = o.scene;
  run.texelSize = atlas.texelSize;
  run.elements = atlas.elements;
  run.charts = atlas.charts.size();
  run.discontinuities = o.discontinuities ? "contact" : "off";
  run.clusters =
      std::size_t(std::count_if(atlas.charts.begin(), atlas.charts.end(), [](const Chart& c) { return c.clustered; }));
  method.describe(run);
  run.atlasWidth = atlas.width;
  run.atlasHeight = atlas.height;
  run.timings = method.solver().timings();
  run.convergenceHistory = method.solver().convergenceHistory();
  return run;
}

}  // namespace

int runSolve(const SolveOptions& o) { return o.method->solve(o); }

int AtlasMethod::solve(const SolveOptions& o) const {
  const auto began = std::chrono::steady_clock::now();
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
  if (o.msaa.value_or(1) > gl::limits().cameraSamples)
    throw InputError(fmt::format("--msaa {}: the {} backend ({}) offers at most {} samples a pixel", *o.msaa,
                                 backend->name(), backend->renderer(), gl::limits().cameraSamples));
  Discretisation d = o.discretisation;
  SubdivideOptions subdivide = o.subdivide;
  if (subdivide.adaptive && !d.texelSize) {  // --elements is the final layout's count
    subdivide.budget = d.elements.value_or(Discretisation::kDefaultElements);
    d.elements = subdivide.budget / SubdivideOptions::kFirstRoundShare;
  }
  announceImagePlan(o, *this);
  Atlas atlas = buildAtlas(scene, d, backend->maxTextureSize());
  if (o.discontinuities) cutAtContacts(scene, atlas, backend->maxTextureSize(), d.chartAngle);
  if (subdivide.adaptive) {  // from here on, the refined (cut, if any) scene and atlas are the solve's
    AdaptiveLayout adaptive = refineAdaptively(subdivide, *this, scene, atlas, camera, double(o.width) / o.height,
                                               backend->maxTextureSize(), d.chartAngle);
    if (adaptive.refined) scene = std::move(adaptive.refined->scene), atlas = std::move(*adaptive.atlas);
  }
  SolverState state(scene, atlas);
  const std::unique_ptr<AtlasRun> run = start(state);
  Solver& solver = run->solver();
  const nlohmann::json identity = checkpointIdentity(scene, atlas, *this, solver);
  SolveStatus status;
  if (resumed) {
    checkResumable(o.resume, resumed->identity, identity);
    state.restore(resumed->radiosity, resumed->deltaB);
    status = solver.restoreState(resumed->solver);
    resumed.reset();
  }
  if (!o.cameraPath.empty()) return run->walkthrough(o, scene, atlas, state, camera);
  run->look(camera, double(o.width) / o.height);  // after a restore: no change

  Progress progress(stop(), o.progress);
  if (int interrupted = solveInBatches(o, state, solver, identity, status, progress)) return interrupted;
  const double solveMs = progress.elapsedSeconds() * 1e3;
  const std::vector<glm::vec4> B = state.readRadiosity();
  OutputBatch outputs;  // all or none: a full disk on the last leaves none of the others
  RunInfo info = describeRun(o, *backend, atlas, *run);
  const std::string lightmapLine = stageImages(outputs, o, scene, atlas, state, *run, camera, B, info);

  info.status = status;
  info.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - began).count();
  info.radiosityHash = radiosityHash(atlas, B);
  info.objects = objectRadiosity(scene, atlas, B);
  info.texelSize /= scene.unitScale;  // lengths and areas in the file's units
  for (ObjectRadiosity& ob : info.objects) ob.area /= scene.unitScale * scene.unitScale;
  if (!o.report.empty()) outputs.add("--report", o.report, reportJson(info).dump(2) + "\n");
  outputs.commit();
  fmt::print(stderr, "{}", lightmapLine);
  fmt::print(stderr, "hemirad: {}: {} elements, {} in {:.0f} ms ({}, {})\n", o.scene, atlas.elements,
             run->reached(status), solveMs, backend->name(), backend->renderer());
  return 0;
}

}  // namespace hemirad
