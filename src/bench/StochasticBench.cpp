#include "src/bench/StochasticBench.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>

#include "src/base/Clock.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/StochasticSolver.h"

namespace hemirad {

namespace {

struct StochasticRow {
  std::string scene;
  int side = 0, width = 0, height = 0, shooters = 0, itemResolution = 0;
  std::size_t elements = 0, itemTriangles = 0;
  unsigned iterations = 0;
  double msPerIteration = 0;  // wall, untimed run
  PassTimings split;          // ms per iteration, synchronised: select = pyramid + selection, gather = update
  std::uint64_t hash = 0;
};

// The finest texel size whose atlas fits `side` texels a side (bisection on the size).
Atlas atlasFilling(const Scene& scene, int side, int maxTexture, double angle) {
  double fits = texelSizeForElements(scene, 1000, angle), tooFine = fits;
  while (true) {
    Atlas a = buildAtlas(scene, tooFine, maxTexture, 0, angle);
    if (std::max(a.width, a.height) > side) break;
    fits = tooFine, tooFine /= 2;
  }
  for (int k = 0; k < 12; ++k) {
    const double mid = 0.5 * (fits + tooFine);
    Atlas a = buildAtlas(scene, mid, maxTexture, 0, angle);
    (std::max(a.width, a.height) > side ? tooFine : fits) = mid;
  }
  return buildAtlas(scene, fits, maxTexture, 0, angle);
}

// Runs to the solver's stop rule from B = E; returns the wall milliseconds (setup excluded).
double run(gl::RenderBackend& backend, StochasticSolver& solver) {
  backend.finish();
  const auto t0 = Clock::now();
  advanceToStop(solver, {});
  backend.finish();
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

StochasticRow benchOne(gl::RenderBackend& backend, const Scene& scene, const Atlas& atlas, int shooters,
                       const BenchOptions& o) {
  StochasticRow row;
  row.width = atlas.width, row.height = atlas.height, row.elements = atlas.elements, row.shooters = shooters;
  row.iterations = o.iterations;
  StochasticSettings settings;
  settings.shooters = shooters;
  settings.itemSubdivision = o.progressive.itemSubdivision;
  settings.itemResolution = o.progressive.itemResolution;
  settings.projection = o.progressive.projection;
  settings.timings = gl::TimerMode::Off;
  settings.stop.maxShots = 1;  // warm-up: shaders compile and buffers page in at first use
  {
    SolverState state(scene, atlas);
    StochasticSolver warm(state, settings);
    run(backend, warm);
  }
  settings.stop.maxShots = o.iterations;
  SolverState state(scene, atlas);
  StochasticSolver solver(state, settings);
  row.msPerIteration = run(backend, solver) / o.iterations;
  row.hash = radiosityHash(atlas, state.readRadiosity());
  row.itemResolution = solver.itemResolution();
  row.itemTriangles = solver.itemTriangles();
  settings.timings = gl::TimerMode::Synchronous;
  SolverState fresh(scene, atlas);
  StochasticSolver timed(fresh, settings);
  run(backend, timed);
  const PassTimings& t = timed.timings();
  row.split = {t.itemBuffer / o.iterations, t.gather / o.iterations, t.select / o.iterations,
               t.readback / o.iterations};
  return row;
}

nlohmann::json rowJson(const StochasticRow& r) {
  return {{"scene", r.scene},
          {"atlas_side", r.side},
          {"atlas", {r.width, r.height}},
          {"elements", r.elements},
          {"shooters_per_iteration", r.shooters},
          {"item_resolution", r.itemResolution},
          {"item_triangles", r.itemTriangles},
          {"iterations", r.iterations},
          {"ms_per_iteration", r.msPerIteration},
          {"split_ms_per_iteration",
           {{"pyramid_select", r.split.select}, {"item_buffer", r.split.itemBuffer}, {"update", r.split.gather}}},
          {"radiosity_hash", fmt::format("{:016x}", r.hash)}};
}

}  // namespace

nlohmann::json benchStochastic(gl::RenderBackend& backend, const BenchOptions& o,
                               const std::function<void(const std::string&)>& say) {
  say("| scene | atlas side | atlas | elements | shooters/iteration | item res | iterations | ms/iteration | "
      "pyramid + select ms | item buffer ms | update ms |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& path : o.scenes) {
    Scene scene = loadScene(path);
    validateSolvable(scene);
    for (int side : o.atlasSides) {
      const Atlas atlas = atlasFilling(scene, side, backend.maxTextureSize(), o.chartAngle);
      for (int k : o.shootersPerPass) {
        StochasticRow r = benchOne(backend, scene, atlas, k, o);
        r.scene = path, r.side = side;
        say(fmt::format("| {} | {} | {} x {} | {} | {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} |\n", r.scene,
                        r.side, r.width, r.height, r.elements, r.shooters, r.itemResolution, r.iterations,
                        r.msPerIteration, r.split.select, r.split.itemBuffer, r.split.gather));
        rows.push_back(rowJson(r));
      }
    }
  }
  return rows;
}

}  // namespace hemirad
