// A walkthrough (seed 004's interactive use, made measurable): the camera follows a path, and
// for every frame the solver shoots within a budget (solver milliseconds, or a shot count for
// reproducible runs), then the frame is rendered, compared with the converged solution seen
// from the same camera, and logged.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "src/output/Image.h"
#include "src/output/Renderer.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/walk/CameraPath.h"

namespace hemirad {

struct WalkthroughOptions {
  double fps = 10;          // frames per second of path time
  double frameMs = 100;     // solver time per frame
  unsigned frameShots = 0;  // instead: this many radiosity shots per frame (reproducible)
  int width = 256, height = 256, supersample = 1;
  bool ambient = true;    // seed 004's display-only ambient term on the frames
  double exposure = 0;    // stops over the automatic exposure of the first converged frame
  std::string framesDir;  // frame_NNNN.png per frame (empty: none), written by writeFrame
  bool progress = false;  // a line on stderr every few seconds: frame k of n
  // (writePng of output/ImageFile.h: passed in, so walkthroughs need no image library).
  std::function<void(const std::string& path, const Image& image, double exposureScale)> writeFrame;
};

struct FrameRecord {
  int frame = 0;
  double time = 0;     // path seconds
  double solveMs = 0;  // solver wall time so far (look() included)
  unsigned shots = 0, importanceShots = 0, deliveryShots = 0;
  double convergence = 0;  // of the whole scene (docs/design.md#convergence)
  // Of the visible part: the light in the frame (without the ambient term) over the light in
  // the converged frame, i.e. how much of what the camera will see has arrived.
  double visibleConvergence = 0;
  double imageError = 0;              // of the frame's B (no ambient term) vs the converged frame (Image.h)
  double shownError = 0;              // of the frame as shown (with the ambient term if on)
  double imageRms = 0, shownRms = 0;  // the same two as relative RMS (imageRmsError)
};

// The converged solution (progressive refinement), rendered from any camera: the reference.
class ConvergedViews {
 public:
  // The reference solve shows the progress bar when `progress` (it can take minutes).
  ConvergedViews(const Scene& scene, const Atlas& atlas, ProgressiveSettings settings, double convergence,
                 bool progress);
  Image render(const Camera& camera, int width, int height, int supersample) {
    return renderer_.render(camera, width, height, supersample);
  }
  unsigned shots() const { return shots_; }

 private:
  SolverState state_;
  Renderer renderer_;
  unsigned shots_ = 0;
};

// Runs the path on `solver` (fresh or not) over `state`, frame by frame.
std::vector<FrameRecord> walk(ProgressiveSolver& solver, SolverState& state, const CameraPath& path,
                              ConvergedViews& converged, const WalkthroughOptions& options);
void writeFramesCsv(const std::string& path, const std::vector<FrameRecord>& frames);

}  // namespace hemirad
