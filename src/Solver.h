// The seam between the CLI and the radiosity algorithms. Each algorithm advances a
// SolverState shot by shot (or iteration by iteration) and says where it stands.
#pragma once
#include <string>
#include <vector>

namespace hemirad {

struct SolveStatus {
  unsigned shots = 0;
  double convergence = 0;  // DESIGN.md: 1 - sum |dB| A / sum E A (luminance)
  bool done = false;       // the stop rule fired
};

// Milliseconds spent per pass, summed over the run (GPU time for GPU passes).
struct PassTimings {
  double itemBuffer = 0, gather = 0, select = 0, readback = 0;
};

struct StopRule {
  unsigned maxShots = 0;         // 0: no limit
  double targetConvergence = 0;  // 0: none
};

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string algorithm() const = 0;
  // Runs up to `shots` more shots, fewer if the stop rule fires, and reports the state after.
  virtual SolveStatus advance(unsigned shots) = 0;
  virtual const PassTimings& timings() const = 0;
  // Convergence after 0, 1, 2, ... shots.
  virtual std::vector<float> convergenceHistory() const = 0;
};

}  // namespace hemirad
