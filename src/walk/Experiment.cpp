#include "src/walk/Experiment.h"

#include <filesystem>
#include <fmt/format.h>

#include "src/base/AtomicFile.h"
#include "src/scene/Atlas.h"
#include "src/base/Error.h"
#include "src/base/DataDir.h"
#include "src/output/Figure.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

namespace {

// Seed 004 §6 times "significant lighting events" in the view; here they are thresholds on
// what the frames measure, the first frame that reaches each.
struct LightingEvent {
  const char* name;
  bool (*reached)(const FrameRecord&);
};
const LightingEvent kEvents[] = {
    {"visible 50 %", [](const FrameRecord& r) { return r.visibleConvergence >= 0.5; }},
    {"visible 75 %", [](const FrameRecord& r) { return r.visibleConvergence >= 0.75; }},
    {"visible 90 %", [](const FrameRecord& r) { return r.visibleConvergence >= 0.9; }},
    {"error < 25 %", [](const FrameRecord& r) { return r.imageError < 0.25; }},
    {"error < 10 %", [](const FrameRecord& r) { return r.imageError < 0.10; }},
    {"error < 5 %", [](const FrameRecord& r) { return r.imageError < 0.05; }},
};

struct Run {
  std::string scene, algorithm;
  std::size_t elements = 0;
  unsigned referenceShots = 0;
  std::vector<FrameRecord> frames;
};

const FrameRecord* firstReaching(const Run& run, const LightingEvent& e) {
  for (const FrameRecord& r : run.frames)
    if (e.reached(r)) return &r;
  return nullptr;
}

double meanOf(const Run& run, double FrameRecord::*field) {
  double sum = 0;
  for (const FrameRecord& r : run.frames) sum += r.*field;
  return sum / double(run.frames.size());
}

std::string summaryMarkdown(const std::vector<Run>& runs, const ExperimentOptions& o, const std::string& renderer) {
  std::string md = fmt::format(
      "# Seed 004's experiments, measured by hemirad\n\n"
      "`hemirad experiment` on {}: each algorithm walks the scene's camera path (SCENE.path) at {} frames per "
      "path second with {} ms of solver time per frame; every frame is compared with progressive refinement "
      "converged to {}. Times are solver milliseconds (with the frame's `look()`), shots are radiosity shots.\n\n"
      "Lighting events: the first frame at which the visible convergence (light in the frame / light in the "
      "converged frame) or the image error (mean |luminance difference| / mean luminance, of B without the ambient "
      "term) reaches a threshold; `-` never on the path. The error with ambient is that of the frames as shown "
      "with seed 004's ambient term.\n\n",
      renderer, o.walkthrough.fps, o.walkthrough.frameMs, o.referenceConvergence);
  md += "| scene | elements | algorithm | shots | deliveries | mean image error | mean error with ambient | mean visible convergence |";
  for (const LightingEvent& e : kEvents) md += fmt::format(" {} (ms / shots) |", e.name);
  md += "\n|---|---|---|---|---|---|---|---|";
  for (std::size_t k = 0; k < std::size(kEvents); ++k) md += "---|";
  md += "\n";
  for (const Run& run : runs) {
    const FrameRecord& last = run.frames.back();
    md += fmt::format("| {} | {} | {} | {} | {} | {:.4f} | {:.4f} | {:.4f} |", run.scene, run.elements, run.algorithm,
                      last.shots, last.deliveryShots, meanOf(run, &FrameRecord::imageError),
                      meanOf(run, &FrameRecord::shownError), meanOf(run, &FrameRecord::visibleConvergence));
    for (const LightingEvent& e : kEvents) {
      const FrameRecord* r = firstReaching(run, e);
      md += r ? fmt::format(" {:.0f} / {} |", r->solveMs, r->shots) : std::string(" - |");
    }
    md += "\n";
  }
  return md;
}

void plotScene(Figures& figures, const std::string& out, const std::string& scene, const std::vector<Run>& runs) {
  LinePlot error{scene + ": image error along the path", "solver time (s)", "image error vs converged", false, true, {}};
  LinePlot visible{scene + ": visible convergence along the path", "solver time (s)", "light in frame / converged", false, false, {}};
  for (const Run& run : runs) {
    if (run.scene != scene) continue;
    PlotSeries e{run.algorithm, {}, {}}, v{run.algorithm, {}, {}};
    for (const FrameRecord& r : run.frames) {
      e.x.push_back(r.solveMs / 1e3), e.y.push_back(std::max(r.imageError, 1e-4));
      v.x.push_back(r.solveMs / 1e3), v.y.push_back(r.visibleConvergence);
    }
    error.series.push_back(e);
    visible.series.push_back(v);
  }
  figures.add(out + "/" + scene + "_image_error", error);
  figures.add(out + "/" + scene + "_visible_convergence", visible);
}

}  // namespace

int runExperiment(ExperimentOptions o) {
  std::filesystem::create_directories(o.out);
  checkWritable(o.out + "/summary.md", "--out-dir");
  o.backend.kind = gl::parseBackendKind(o.backendName);
  for (std::string& s : o.scenes) s = findScene(s);  // the shipped scenes from any directory
  checkPlotting();
  auto backend = gl::createBackend(o.backend);
  std::vector<Run> runs;
  std::vector<std::string> names;
  for (const std::string& path : o.scenes) {
    const Scene scene = loadScene(path);
    validateSolvable(scene);
    const std::string name = std::filesystem::path(path).stem().string();
    const std::string pathFile = std::filesystem::path(path).replace_extension(".path").string();
    if (!std::filesystem::exists(pathFile)) throw InputError(fmt::format("{}: no camera path {} beside it", path, pathFile));
    const CameraPath cameraPath = readCameraPath(pathFile, resolveCamera(scene, std::nullopt));
    const Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, o.elements), backend->maxTextureSize());
    ConvergedViews converged(scene, atlas, o.progressive, o.referenceConvergence);
    names.push_back(name);
    for (const std::string& algorithm : o.algorithms) {
      SolverState state(scene, atlas);
      ProgressiveSettings settings = o.progressive;
      settings.algorithm = parseAlgorithm(algorithm);
      settings.stop = {0, 0.99999};
      ProgressiveSolver solver(state, settings);
      WalkthroughOptions w = o.walkthrough;
      w.framesDir = o.frames ? fmt::format("{}/{}_{}", o.out, name, algorithm) : "";
      Run run{name, algorithm, atlas.elements, converged.shots(), walk(solver, state, cameraPath, converged, w)};
      writeFramesCsv(fmt::format("{}/{}_{}.csv", o.out, name, algorithm), run.frames);
      const FrameRecord& last = run.frames.back();
      fmt::print(stderr, "hemirad: {} {}: {} frames, {} shots, mean image error {:.4f}\n", name, algorithm,
                 run.frames.size(), last.shots, meanOf(run, &FrameRecord::imageError));
      runs.push_back(std::move(run));
    }
  }
  std::string csv = "scene,elements,algorithm,event,solve_ms,shots\n";
  for (const Run& run : runs)
    for (const LightingEvent& e : kEvents) {
      const FrameRecord* r = firstReaching(run, e);
      csv += r ? fmt::format("{},{},{},{},{:.2f},{}\n", run.scene, run.elements, run.algorithm, e.name, r->solveMs, r->shots)
               : fmt::format("{},{},{},{},,\n", run.scene, run.elements, run.algorithm, e.name);
    }
  writeTextFile(o.out + "/events.csv", csv);
  Figures figures(provenance(backend->name(), backend->renderer()));
  for (const std::string& name : names) plotScene(figures, o.out, name, runs);
  figures.write();
  const std::string md = summaryMarkdown(runs, o, fmt::format("{} ({})", backend->name(), backend->renderer()));
  writeTextFile(o.out + "/summary.md", md);
  fmt::print("{}", md);
  return 0;
}

}  // namespace hemirad
