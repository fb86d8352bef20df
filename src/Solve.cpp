#include "src/Solve.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "src/AtomicFile.h"
#include "src/Atlas.h"
#include "src/Camera.h"
#include "src/Error.h"
#include "src/Image.h"
#include "src/PlyWriter.h"
#include "src/Progress.h"
#include "src/Renderer.h"
#include "src/Report.h"

namespace hemirad {

double chooseTexelSize(const Scene& scene, const Discretisation& d) {
  if (d.texelSize) return *d.texelSize;
  return texelSizeForElements(scene, d.elements.value_or(Discretisation::kDefaultElements));
}

namespace {

Image atlasImage(const Atlas& atlas, const std::vector<glm::vec4>& B) {
  Image img{atlas.width, atlas.height, std::vector<float>(B.size() * 3)};
  for (size_t t = 0; t < B.size(); ++t)
    for (int c = 0; c < 3; ++c) img.rgb[t * 3 + c] = B[t][c];
  return img;
}

}  // namespace

int runSolve(const SolveOptions& o) {
  auto start = std::chrono::steady_clock::now();
  for (auto [path, flag] : {std::pair{o.out, "--out"}, {o.image, "--image"}, {o.atlas, "--atlas"}, {o.ply, "--ply"},
                            {o.report, "--report"}})
    if (!path.empty()) checkWritable(path, flag);

  Scene scene = loadScene(o.scene, o.load);
  for (const auto& w : scene.warnings) warn(w);
  validateSolvable(scene);
  Camera camera = resolveCamera(scene, o.camera);

  auto backend = gl::createBackend(o.backend);
  if (o.backend.kind == gl::BackendKind::Auto)
    fmt::print(stderr, "hemirad: backend auto chose {} ({})\n", backend->name(), backend->renderer());
  Atlas atlas = buildAtlas(scene, chooseTexelSize(scene, o.discretisation), backend->maxTextureSize());
  SolverState state(scene, atlas);
  ProgressiveSolver solver(state, o.progressive);

  Progress progress(o.progressive.stop, o.progress);
  SolveStatus status;
  for (unsigned batch = 1; !status.done;) {
    auto t0 = std::chrono::steady_clock::now();
    status = solver.advance(batch);
    progress.update(status);
    batch = nextBatch(batch, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  progress.finish();
  double solveMs = progress.elapsedSeconds() * 1e3;

  std::vector<glm::vec4> B = state.readRadiosity();
  Image view;
  double scale = 1;
  if (!o.out.empty() || !o.image.empty() || !o.ply.empty()) {
    view = Renderer(state).render(camera, o.width, o.height, o.supersample);
    scale = exposureScale(view, o.exposure);
  }
  if (!o.out.empty()) writeExr(o.out, view);
  if (!o.image.empty()) writePng(o.image, view, scale);
  if (!o.atlas.empty()) writeExr(o.atlas, atlasImage(atlas, B));
  if (!o.ply.empty()) writePly(o.ply, scene, atlas, B, scale);

  RunInfo run;
  run.backend = backend->name();
  run.renderer = backend->renderer();
  run.algorithm = solver.algorithm();
  run.scene = o.scene;
  run.texelSize = atlas.texelSize;
  run.itemSubdivision = o.progressive.itemSubdivision;
  run.itemResolution = o.progressive.itemResolution;
  run.shootLevel = o.progressive.shootLevel;
  run.elements = atlas.elements;
  run.itemTriangles = solver.itemTriangles();
  run.atlasWidth = atlas.width;
  run.atlasHeight = atlas.height;
  run.status = status;
  run.timings = solver.timings();
  run.totalMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  run.radiosityHash = radiosityHash(atlas, B);
  run.objects = objectRadiosity(scene, atlas, B);
  run.convergenceHistory = solver.convergenceHistory();
  if (!o.report.empty()) writeReport(o.report, run);

  fmt::print(stderr, "hemirad: {}: {} elements, {} shots, convergence {:.4f} in {:.0f} ms ({}, {})\n", o.scene,
             atlas.elements, status.shots, status.convergence, solveMs, backend->name(), backend->renderer());
  return 0;
}

}  // namespace hemirad
