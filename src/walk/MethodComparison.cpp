#include "src/walk/MethodComparison.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>

#include "src/base/AtomicFile.h"
#include "src/base/Clock.h"
#include "src/base/DataDir.h"
#include "src/base/OutputPaths.h"
#include "src/output/Figure.h"
#include "src/scene/SceneLoader.h"
#include "src/walk/SolutionError.h"

namespace hemirad {

namespace {

struct Sample {
  unsigned shots = 0;  // progressive shots or stochastic iterations
  double solverMs = 0, error = 0;
};

// Batches of doubling size until `done`; only advance() and the wait for the GPU are timed.
std::vector<Sample> trace(gl::RenderBackend& backend, const SolverState& state, Solver& solver,
                          const std::vector<glm::vec4>& reference, const std::function<bool(const Sample&)>& done) {
  std::vector<Sample> out;
  Sample s;
  for (unsigned batch = 1; !done(s); batch *= 2) {
    backend.finish();
    const auto t0 = Clock::now();
    const SolveStatus status = solver.advance(batch);
    backend.finish();
    s.solverMs += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    s.shots = status.shots;
    s.error = relativeRmsError(state.scene, state.atlas, state.readRadiosity(), reference);
    out.push_back(s);
    if (status.done) break;
  }
  return out;
}

std::string csv(const std::string& method, const std::vector<Sample>& samples) {
  std::string out;
  for (const Sample& s : samples) out += fmt::format("{},{},{:.3f},{:.6g}\n", method, s.shots, s.solverMs, s.error);
  return out;
}

PlotSeries series(const std::string& label, const std::vector<Sample>& samples) {
  PlotSeries p{label, {}, {}};
  for (const Sample& s : samples) p.x.push_back(s.solverMs), p.y.push_back(s.error);
  return p;
}

}  // namespace

int runMethodComparison(MethodComparisonOptions o) {
  if (o.out.empty()) o.out = freshFolder("hemirad-compare-methods");  // no --out-dir
  fmt::print(stderr, "hemirad: writing into {}\n", o.out);
  for (std::string& s : o.scenes) s = findScene(s);  // the shipped scenes from any directory
  checkPlotting();
  auto backend = gl::createBackend(o.backend);
  Figures figures(provenance(backend->name(), backend->renderer()), parseFigureSize(o.figureSize));
  std::filesystem::create_directories(o.out);
  std::string summary = fmt::format(
      "# Error against solver time: progressive vs stochastic ({}, {})\n\n"
      "| scene | elements | method | shots / iterations | solver ms | RMS error / mean (non-emitters) |\n"
      "|---|---|---|---|---|---|\n",
      backend->name(), backend->renderer());
  for (const std::string& path : o.scenes) {
    const Scene scene = loadScene(path);
    validateSolvable(scene);
    // Both methods share the default atlas.
    const Atlas atlas =
        buildAtlas(scene, Discretisation{.texelSize = {}, .elements = o.elements}, backend->maxTextureSize());
    ProgressiveSettings p = o.progressive;
    p.shootLevel = 0;  // one-texel shooters, as stochastic iteration's: the same discrete operator
    p.timings = gl::TimerMode::Off;
    p.stop = {0, o.referenceConvergence};
    SolverState refState(scene, atlas);
    ProgressiveSolver refSolver(refState, p);
    advanceToStop(refSolver, {});
    const std::vector<glm::vec4> reference = refState.readRadiosity();

    StochasticSettings st;
    st.seed = o.seed, st.shooters = p.shootersPerPass, st.itemSubdivision = p.itemSubdivision;
    st.itemResolution = p.itemResolution, st.projection = p.projection, st.timings = gl::TimerMode::Off;
    st.stop = {o.iterations, 0};
    SolverState stState(scene, atlas);
    StochasticSolver stochastic(stState, st);
    const std::vector<Sample> stSamples =
        trace(*backend, stState, stochastic, reference, [](const Sample&) { return false; });
    SolverState prState(scene, atlas);
    ProgressiveSolver progressive(prState, p);
    const double budget = stSamples.back().solverMs;
    const std::vector<Sample> prSamples =
        trace(*backend, prState, progressive, reference, [budget](const Sample& s) { return s.solverMs > budget; });

    const std::string name = std::filesystem::path(path).stem().string();
    writeTextFile(
        o.out + "/" + name + "_methods.csv",
        "method,shots,solver_ms,relative_rms_error\n" + csv("progressive", prSamples) + csv("stochastic", stSamples));
    figures.add(o.out + "/" + name + "_error_vs_time",
                LinePlot{fmt::format("{}: {} elements", name, atlas.elements),
                         "solver time (ms)",
                         "RMS error of luminance / mean (non-emitters)",
                         true,
                         true,
                         {series("progressive (K = " + std::to_string(p.shootersPerPass) + ")", prSamples),
                          series("stochastic (K = " + std::to_string(st.shooters) + ")", stSamples)}});
    for (const auto& [method, samples] : {std::pair{"progressive", &prSamples}, {"stochastic", &stSamples}})
      summary += fmt::format("| {} | {} | {} | {} | {:.0f} | {:.4f} |\n", name, atlas.elements, method,
                             samples->back().shots, samples->back().solverMs, samples->back().error);
    fmt::print(stderr, "hemirad: {}: reference to {}, {} samples each, into {}\n", name, o.referenceConvergence,
               stSamples.size(), o.out);
  }
  figures.write();
  writeTextFile(o.out + "/summary.md", summary);
  return 0;
}

}  // namespace hemirad
