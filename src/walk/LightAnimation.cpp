#include "src/walk/LightAnimation.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/ImageFile.h"
#include "src/output/Renderer.h"
#include "src/output/ShownRadiosity.h"
#include "src/scene/Camera.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/walk/LightPath.h"
#include "src/walk/SolutionError.h"

namespace hemirad {

namespace {

// The converged progressive solution of one frame's scene, one-texel shooters as stochastic's.
std::vector<glm::vec4> reference(const Scene& scene, const Atlas& atlas, const AnimationOptions& o) {
  ProgressiveSettings p;
  p.shootLevel = 0;
  p.itemSubdivision = o.stochastic.itemSubdivision;
  p.itemResolution = o.stochastic.itemResolution;
  p.timings = gl::TimerMode::Off;
  p.stop = {0, o.referenceConvergence};
  SolverState state(scene, atlas);
  ProgressiveSolver solver(state, p);
  advanceToStop(solver, {});
  return state.readRadiosity();
}

// What carries from frame to frame: the running mean, the iterate and the solver's state.
struct Carried {
  std::vector<glm::vec4> B, L;
  std::vector<std::uint8_t> solver;
};

}  // namespace

int runAnimation(AnimationOptions o) {
  const LightPath path = readLightPath(o.lightPath);
  const Scene base = loadScene(o.scene, o.load);
  validateSolvable(base);
  const Camera camera = resolveCamera(base, o.camera);
  auto backend = gl::createBackend(o.backend);
  const Discretisation& d = o.discretisation;
  const Atlas baseAtlas = buildAtlas(base, d, backend->maxTextureSize());
  std::filesystem::create_directories(o.framesDir);
  const unsigned frames = unsigned(std::floor(path.duration() * o.fps + 1e-9)) + 1;
  std::string csv = "frame,time,iterations,relative_rms_error,radiosity_hash\n";
  Carried carried;
  double exposure = 0;  // frame 0's, kept: a moving light changes the picture, not its exposure
  for (unsigned f = 0; f < frames; ++f) {
    const double time = f / o.fps;
    const glm::dvec3 offset = path.at(time) * base.unitScale;  // the path is in the file's units
    const Scene scene = withLightsMoved(base, offset);
    const Atlas atlas = withLightsMoved(baseAtlas, base, offset);
    SolverState state(scene, atlas);
    StochasticSettings settings = o.stochastic;
    settings.stop.maxShots = (f + 1) * o.frameIterations;
    StochasticSolver solver(state, settings);
    if (f > 0) {  // the same layout (translation only): go on from where it stood
      state.restore(carried.B, carried.L);
      solver.restoreState(carried.solver);
    }
    const SolveStatus status = advanceToStop(solver, {});
    carried = {state.readRadiosity(), state.readDeltaB(), solver.saveState()};
    const double error = relativeRmsError(scene, atlas, carried.B, reference(scene, atlas, o));
    Renderer renderer(state);
    renderer.show(shownRadiosity(scene, atlas, carried.B));  // as solve's images
    const Image view = renderer.render(camera, o.width, o.height, 1);
    if (f == 0) exposure = exposureScale(view, 0);
    writePng(fmt::format("{}/frame_{:04d}.png", o.framesDir, f), view, exposure);
    csv += fmt::format("{},{:.4f},{},{:.6g},{:016x}\n", f, time, status.shots, error, radiosityHash(atlas, carried.B));
  }
  writeTextFile(o.framesDir + "/frames.csv", csv);
  fmt::print(stderr, "hemirad: {}: {} frames along {} ({} iterations each, window {}) into {}\n", o.scene, frames,
             o.lightPath, o.frameIterations, o.stochastic.window, o.framesDir);
  return 0;
}

}  // namespace hemirad
