// `hemirad bench`: time to convergence and the per-pass split of the progressive solver on
// scenes of growing element counts, or (--method stochastic) the cost of one stochastic
// iteration at given atlas sides, as a table and JSON. Speed lives here, never in tests.
#pragma once
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/VplTracer.h"

namespace CLI {
class App;  // CLI11 (src/options/Options.h): parsed only where flags are declared
}

namespace hemirad {

struct BenchOptions {
  std::vector<std::string> scenes{"scenes/cornell/cornell.obj"};
  std::vector<std::size_t> elements{10000, 100000};
  double chartAngle = kDefaultChartAngle;  // --chart-angle (src/scene/Charts.h), as for solve
  double converge = 0.9;
  ProgressiveSettings progressive;         // shoot level, item mesh and buffer as for solve
  std::string method = "progressive";      // which of the bench's runs below
  std::vector<int> atlasSides{512, 1024};  // stochastic: one row per atlas side (texel size fills it)
  unsigned iterations = 8;                 // stochastic: iterations timed per row
  std::vector<int> shootersPerPass{ProgressiveSettings{}.shootersPerPass};  // a row each
  unsigned splitShots = 64;  // shots timed pass by pass (synchronised) for the split
  gl::BackendOptions backend;
  std::string json;
  std::string markdown;                       // the printed tables, as a markdown file
  bool ceiling = false;                       // also measure the device's compute and raster ceilings
  std::string compare;                        // another bench JSON to compare per-object radiosity with
  std::vector<unsigned> vpls{128, 256, 512};  // instant: a row per VPL count
  InstantSettings instant;                    // instant: seed, bounces, clamp, shadow maps
  int width = 1024, height = 1024;            // instant: the frame's size
  std::vector<int> interleave{1, 4};          // instant: a row per interleaving tile side
};

// The bench flags, shared by `hemirad bench` and the lean `hemirad-bench`.
void addBenchFlags(CLI::App* cmd, BenchOptions& options);
int runBench(BenchOptions options);
// The --method names the bench measures, each with a run of its own.
std::vector<std::string> benchMethods();

}  // namespace hemirad
