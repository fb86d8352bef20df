// Stochastic iteration radiosity (seed 000, Barsi & Jakab, "Stream processing in global
// illumination"): every iteration applies a random transport operator T* with E[T* B] = T B,
// L_m = E + T* L_{m-1}, and folds the iterate into their running mean B~ with weight 1/m
// (eq. 2); B~ is SolverState::radiosity, L the deltaB atlas. Source::Mean instead transports
// the mean itself, B~_m = (1 - 1/m) B~_{m-1} + (1/m)(E + T* B~_{m-1}), eq. 2 as printed. T*
// shoots from K texels drawn with probability lum(B~) x area by descending a luminance sum
// pyramid on the GPU (eq. 3), each through an item buffer (seed 003's orthographic by default) and the exact
// point-to-element form factor. The CPU never reads the atlas during a solve: it enqueues
// passes and reads the iteration count between batches. docs/design.md#stochastic-iteration.
#pragma once
#include <memory>

#include "gl/Objects.h"
#include "gl/Shader.h"
#include "gl/Timer.h"
#include "src/solver/ItemBuffer.h"
#include "src/solver/Solver.h"
#include "src/solver/SolverState.h"

namespace hemirad {

// What T* transports each iteration: the last iterate (a Markov chain whose mean converges at
// 1/sqrt(m) with a bias that fades as 1/m), or the running mean (eq. 2 as printed: its bias
// fades only as m^-(1 - lambda), lambda T's spectral radius; docs/design.md#stochastic-iteration).
enum class Source { Iterate, Mean };
Source parseSource(const std::string& name);  // throws InputError
const char* sourceName(Source s);

struct StochasticSettings {
  std::uint32_t seed = 1;  // with the backend, fixes the result bit for bit
  int shooters = 16;       // K texels shot per iteration (1..kMaxPassShooters), averaged inside it
  Source source = Source::Iterate;
  // 0: B is the mean of all iterates (weight 1/m). W > 0: weight max(1/m, 1/W), an exponential
  // window of about W iterations, so B follows a scene that changes (moving lights).
  unsigned window = 0;
  int itemSubdivision = 3;
  int itemResolution = 256;  // item buffer pixels a side; kAutoItemResolution: planned as progressive
  Projection projection = Projection::Orthographic;
  gl::TimerMode timings = gl::TimerMode::Gpu;
  StopRule stop;  // maxShots: iterations (a convergence target does not apply)
};

class StochasticSolver final : public Solver {
 public:
  StochasticSolver(SolverState& state, const StochasticSettings& settings);
  ~StochasticSolver() override;
  std::string algorithm() const override { return "stochastic"; }
  // Runs up to `iterations` more iterations (a shot in SolveStatus counts one iteration).
  SolveStatus advance(unsigned iterations) override;
  const PassTimings& timings() const override { return timings_; }
  // Convergence is not defined for a Monte Carlo estimate: NaN after every iteration (docs/design.md#convergence).
  std::vector<float> convergenceHistory() const override;
  std::vector<std::uint8_t> saveState() const override;  // iteration count and seed
  SolveStatus restoreState(std::span<const std::uint8_t> bytes) override;
  // B <- T* B once, with the draws of iteration `key` and no averaging or emission: what the
  // unbiasedness probe (src/validate/StochasticProbe.h) averages.
  void applyOperator(std::uint32_t key);
  std::size_t itemTriangles() const { return itemBuffer_->triangles(); }
  int itemResolution() const { return itemResolution_; }
  unsigned pyramidSide() const { return side_; }

 private:
  void pyramidPass(const gl::Texture& source);
  void samplePass(const gl::Texture& source, std::uint32_t key);
  void updatePass(float weight, float emission);
  void iterate(const gl::Texture& source, std::uint32_t key, float weight, float emission);

  SolverState& state_;
  StochasticSettings settings_;
  int itemResolution_;
  unsigned side_ = 1, levels_ = 1;  // pyramid level 0's side, level count
  gl::Program pyramid_, sample_, update_;
  gl::Buffer pyramidSums_, charts_, texelParts_, shapes_, control_;
  std::unique_ptr<ItemBuffer> itemBuffer_;
  SolveStatus status_;
  PassTimings timings_;
  gl::GpuTimer timer_;
  double sampled_[3] = {};
  unsigned enqueued_ = 0, timed_ = 0;
};

}  // namespace hemirad
