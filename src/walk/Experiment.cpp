#include "src/walk/Experiment.h"

#include <fmt/format.h>
#include <algorithm>
#include <filesystem>

#include "src/base/AtomicFile.h"
#include "src/base/DataDir.h"
#include "src/base/Error.h"
#include "src/base/OutputPaths.h"
#include "src/output/Figure.h"
#include "src/scene/Atlas.h"
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
  bool still = false;  // the camera never moves: error against shots is the measure
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
      "`hemirad experiment` on {}: each algorithm walks the camera path ({}) at {} frames per "
      "path second with {} per frame; every frame is compared with progressive refinement "
      "converged to {}. Times are solver milliseconds (with the frame's `look()`), shots are radiosity shots.\n\n"
      "Lighting events: the first frame at which the visible convergence (light in the frame / light in the "
      "converged frame) or the image error (mean |luminance difference| / mean luminance, of B without the ambient "
      "term) reaches a threshold; `-` never on the path. The error with ambient is that of the frames as shown "
      "with seed 004's ambient term.\n\n",
      renderer, o.cameraPath.empty() ? "SCENE.path" : o.cameraPath, o.walkthrough.fps,
      o.walkthrough.frameShots ? fmt::format("{} shots", o.walkthrough.frameShots)
                               : fmt::format("{} ms of solver time", o.walkthrough.frameMs),
      o.referenceConvergence);
  md +=
      "| scene | elements | algorithm | shots | deliveries | mean image error | mean error with ambient | mean visible "
      "convergence |";
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

// Issue 19's measures. A still camera: the shots each view-driven algorithm needs to reach the
// image error progressive refinement has after N shots (N = 64, 128, ...), the first frame
// whose error is as low. A moving one: frame by frame, how often one algorithm's frame is at
// least as good as another's, and the mean ratio of their errors.
std::string winsMarkdown(const std::vector<Run>& runs) {
  std::string still, moving;
  for (const Run& p : runs) {
    if (p.algorithm != "progressive") continue;
    for (const Run& a : runs) {
      if (a.scene != p.scene || a.algorithm == "progressive") continue;
      if (p.still) {
        for (unsigned n = 64; n <= p.frames.back().shots; n *= 2) {
          const FrameRecord& at =
              *std::find_if(p.frames.begin(), p.frames.end(), [n](const FrameRecord& r) { return r.shots >= n; });
          const FrameRecord* reach = nullptr;
          for (const FrameRecord& r : a.frames)
            if (!reach && r.imageError <= at.imageError) reach = &r;
          still +=
              reach ? fmt::format("| {} | {} | {} | {:.4f} | {} | {:.1f} |\n", p.scene, a.algorithm, at.shots,
                                  at.imageError, reach->shots, double(at.shots) / reach->shots)
                    : fmt::format("| {} | {} | {} | {:.4f} | - | - |\n", p.scene, a.algorithm, at.shots, at.imageError);
        }
        continue;
      }
      for (const Run& b : runs) {
        if (b.scene != a.scene || b.algorithm == a.algorithm ||
            (a.algorithm == "importance" && b.algorithm != "progressive"))
          continue;
        std::size_t asGood = 0;
        double ratio = 0;
        for (std::size_t f = 0; f < a.frames.size() && f < b.frames.size(); ++f) {
          asGood += a.frames[f].imageError <= b.frames[f].imageError;
          ratio += a.frames[f].imageError / std::max(b.frames[f].imageError, 1e-12);
        }
        moving += fmt::format("| {} | {} vs {} | {} of {} | {:.3f} |\n", a.scene, a.algorithm, b.algorithm, asGood,
                              a.frames.size(), ratio / double(a.frames.size()));
      }
    }
  }
  std::string md;
  if (!still.empty())
    md +=
        "\n## Shots to progressive refinement's error (still camera)\n\n"
        "| scene | algorithm | progressive shots N | its image error | shots to reach it | N / shots |\n"
        "|---|---|---|---|---|---|\n" +
        still;
  if (!moving.empty())
    md +=
        "\n## Frame by frame (moving camera)\n\n"
        "| scene | algorithms | frames with error at most the other's | mean error ratio |\n|---|---|---|---|\n" +
        moving;
  return md;
}

void plotScene(Figures& figures, const std::string& out, const std::string& scene, const std::vector<Run>& runs) {
  const std::string yLabel = "image error vs converged (mean |dL| / mean L)";
  LinePlot error{
      scene + ": image error along the path", "solver time (s)", "image error vs converged", false, true, {}};
  LinePlot visible{scene + ": visible convergence along the path",
                   "solver time (s)",
                   "light in frame / converged",
                   false,
                   false,
                   {}};
  LinePlot byShots{scene + ": image error against shots", "radiosity shots", yLabel, true, true, {}};
  LinePlot byTime{scene + ": image error against solver time", "solver time (ms)", yLabel, true, true, {}};
  for (const Run& run : runs) {
    if (run.scene != scene) continue;
    PlotSeries e{run.algorithm, {}, {}}, v{run.algorithm, {}, {}}, s{run.algorithm, {}, {}}, t{run.algorithm, {}, {}};
    for (const FrameRecord& r : run.frames) {
      e.x.push_back(r.solveMs / 1e3), e.y.push_back(std::max(r.imageError, 1e-4));
      v.x.push_back(r.solveMs / 1e3), v.y.push_back(r.visibleConvergence);
      s.x.push_back(r.shots), s.y.push_back(r.imageError);
      t.x.push_back(r.solveMs), t.y.push_back(r.imageError);
    }
    error.series.push_back(e);
    visible.series.push_back(v);
    byShots.series.push_back(s);
    byTime.series.push_back(t);
  }
  figures.add(out + "/" + scene + "_image_error", error);
  figures.add(out + "/" + scene + "_visible_convergence", visible);
  figures.add(out + "/" + scene + "_error_vs_shots", byShots);
  figures.add(out + "/" + scene + "_error_vs_time", byTime);
}

}  // namespace

int runExperiment(ExperimentOptions o) {
  if (o.out.empty()) o.out = freshFolder("hemirad-experiment");  // no --out-dir
  fmt::print(stderr, "hemirad: writing into {}\n", o.out);
  std::filesystem::create_directories(o.out);
  checkWritable(o.out + "/summary.md", "--out-dir");
  for (std::string& s : o.scenes) s = findScene(s);  // the shipped scenes from any directory
  if (o.figures) checkPlotting();
  parseFigureSize(o.figureSize);  // a bad size fails before the solves
  auto backend = gl::createBackend(o.backend);
  std::vector<Run> runs;
  std::vector<std::string> names;
  for (const std::string& path : o.scenes) {
    const Scene scene = loadScene(path);
    validateSolvable(scene);
    const std::string name = std::filesystem::path(path).stem().string();
    const std::string pathFile =
        o.cameraPath.empty() ? std::filesystem::path(path).replace_extension(".path").string() : o.cameraPath;
    if (!std::filesystem::exists(pathFile))
      throw InputError(fmt::format("{}: no camera path {} beside it", path, pathFile));
    const CameraPath cameraPath = readCameraPath(pathFile, resolveCamera(scene, std::nullopt), scene.unitScale);
    const Atlas atlas = buildAtlas(scene, Discretisation{.texelSize = {}, .elements = o.elements, .chartAngle = 0},
                                   backend->maxTextureSize());
    ConvergedViews converged(scene, atlas, o.progressive, o.referenceConvergence, true);
    names.push_back(name);
    for (const std::string& algorithm : o.algorithms) {
      SolverState state(scene, atlas);
      ProgressiveSettings settings = o.progressive;
      settings.algorithm = parseAlgorithm(algorithm);
      settings.stop = {0, 0.99999};
      ProgressiveSolver solver(state, settings);
      WalkthroughOptions w = o.walkthrough;
      w.framesDir = o.frames ? fmt::format("{}/{}_{}", o.out, name, algorithm) : "";
      const bool still = std::all_of(cameraPath.keys.begin(), cameraPath.keys.end(),
                                     [&](const auto& k) { return k.camera == cameraPath.keys.front().camera; });
      Run run{name, algorithm, atlas.elements, converged.shots(), still, walk(solver, state, cameraPath, converged, w)};
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
      csv += r ? fmt::format("{},{},{},{},{:.2f},{}\n", run.scene, run.elements, run.algorithm, e.name, r->solveMs,
                             r->shots)
               : fmt::format("{},{},{},{},,\n", run.scene, run.elements, run.algorithm, e.name);
    }
  writeTextFile(o.out + "/events.csv", csv);
  if (o.figures) {
    Figures figures(provenance(backend->name(), backend->renderer()), parseFigureSize(o.figureSize));
    for (const std::string& name : names) plotScene(figures, o.out, name, runs);
    figures.write();
  }
  const std::string md =
      summaryMarkdown(runs, o, fmt::format("{} ({})", backend->name(), backend->renderer())) + winsMarkdown(runs);
  writeTextFile(o.out + "/summary.md", md);
  fmt::print("{}", md);
  return 0;
}

}  // namespace hemirad
