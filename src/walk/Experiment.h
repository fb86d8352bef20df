// `hemirad experiment`: seed 004's experiments (§6) as one command. For every scene, each
// algorithm walks the scene's camera path (SCENE.path) with the same solver time per frame;
// every frame is compared with the converged solution. Writes per-run CSVs, a summary of the
// time to lighting events (CSV and markdown) and plots of image error and visible convergence
// over solver time.
#pragma once
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/walk/Walkthrough.h"

namespace hemirad {

struct ExperimentOptions {
  std::vector<std::string> scenes{"scenes/four_boxes/four_boxes.obj", "scenes/four_boxes/four_boxes_x2.obj",
                                  "scenes/cornell_subdivided/cornell_x4.obj"};
  std::vector<std::string> algorithms{"progressive", "importance", "perspective"};
  std::size_t elements = 4000;
  double referenceConvergence = 0.99;
  ProgressiveSettings progressive;
  WalkthroughOptions walkthrough;  // fps, frame budget, frame size
  std::string cameraPath;          // instead of SCENE.path beside each scene (e.g. a still camera)
  std::string out;                 // --out-dir; empty: a fresh ./hemirad-COMMAND folder (freshFolder)
  std::string figureSize;          // --figure-size (parseFigureSize)
  bool frames = false;             // also keep every frame's PNG (written by walkthrough.writeFrame)
  bool figures = true;             // the SVG/PDF plots (matplotlib); without, the CSVs and summary only
  gl::BackendOptions backend;
};

int runExperiment(ExperimentOptions options);

}  // namespace hemirad
