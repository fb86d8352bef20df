// `hemirad animate`: stochastic iteration under moving lights (issue 15). The emitters follow a
// light path (LightPath.h); per frame the scene is moved, the solver goes on from the previous
// frame's running mean and iterate with an exponential window (StochasticSettings::window)
// instead of restarting, runs --frame-shots iterations, and the frame is rendered and compared
// with a converged progressive solve of that frame. Writes frame_NNNN.png and frames.csv.
#pragma once
#include <string>

#include "gl/Backend.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/StochasticSolver.h"

namespace hemirad {

struct AnimationOptions {
  std::string scene, lightPath, framesDir;
  LoadOptions load;
  Discretisation discretisation;
  std::optional<std::string> camera;
  double fps = 10;
  unsigned frameIterations = 32;        // --frame-shots
  double referenceConvergence = 0.999;  // each frame's progressive reference
  StochasticSettings stochastic;        // window: --window (default 64)
  int width = 256, height = 256;
  gl::BackendOptions backend;
};

int runAnimation(AnimationOptions options);

}  // namespace hemirad
