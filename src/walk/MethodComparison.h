// `hemirad compare-methods`: error against solver time for progressive refinement and
// stochastic iteration in the same run, per scene: both start from E on the same atlas, the
// error after each batch is relativeRmsError (SolutionError.h) against a converged progressive
// solution. Writes a CSV per scene, an SVG figure (log-log) and
// a markdown summary.
#pragma once
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/StochasticSolver.h"

namespace hemirad {

struct MethodComparisonOptions {
  std::vector<std::string> scenes{"scenes/cornell/cornell.obj", "scenes/four_boxes/four_boxes.obj"};
  std::size_t elements = 2000;
  double referenceConvergence = 0.9999;  // the reference, and where the progressive run stops
  unsigned iterations = 1024;            // stochastic iterations; progressive gets the same solver time at most
  ProgressiveSettings progressive;       // item buffer, shooters per pass (also the stochastic K)
  std::uint32_t seed = 1;
  std::string out;         // --out-dir; empty: a fresh ./hemirad-COMMAND folder (freshFolder)
  std::string figureSize;  // --figure-size (parseFigureSize)
  gl::BackendOptions backend;
};

int runMethodComparison(MethodComparisonOptions options);

}  // namespace hemirad
