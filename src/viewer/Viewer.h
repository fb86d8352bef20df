// `hemirad view SCENE`: a window (GLFW) showing the solution refine live, with mouse and
// keyboard camera control and a switch between the algorithms.
#pragma once
#include <optional>
#include <string>

#include "gl/Backend.h"
#include "src/output/InstantRenderer.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ProgressiveSolver.h"

namespace hemirad {

struct ViewerOptions {
  std::string scene;
  LoadOptions load;
  Discretisation discretisation;
  ProgressiveSettings progressive = [] {
    ProgressiveSettings p;
    p.stop.targetConvergence = 0.999;  // the viewer stops only when there is little left to see
    return p;
  }();
  std::string method = "progressive";  // or instant: VPLs traced once, each frame shaded from them
  InstantSettings instant;
  Shading shading = Shading::Deferred;
  gl::BackendOptions backend;
  std::optional<std::string> camera;
  int width = 800, height = 600;
  double exposure = 0;
  bool ambient = true;         // seed 004's display-only ambient term
  double frameMs = 33;         // solver time budget per frame
  unsigned shotsPerFrame = 0;  // instead of the budget: exactly this many shots a frame (deterministic)
  unsigned frames = 0;         // quit after this many frames (0: when the window closes)
  std::string screenshot;      // PNG of the window's last frame, written on quit
};

// The mouse and key controls, for --help and the terminal.
const char* viewerControls();
int runView(ViewerOptions options);

}  // namespace hemirad
