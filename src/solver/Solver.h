// The seam between the CLI and the radiosity algorithms. Each algorithm advances a
// SolverState shot by shot (or iteration by iteration) and says where it stands.
#pragma once
#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace hemirad {

// Progressive refinement's shooter choices, `--algorithm`: importance- and perspective-driven
// shooting (seed 004) run on the progressive solver. The methods (`--method`) are units of
// their own, src/method/MethodUnit.h; stochastic iteration's Solver names its algorithm
// "stochastic".
enum class Algorithm { Progressive, Importance, Perspective };
Algorithm parseAlgorithm(const std::string& name);  // throws InputError
const char* algorithmName(Algorithm a);
inline const std::vector<std::string>& algorithmNames() {
  static const std::vector<std::string> names{"progressive", "importance", "perspective"};
  return names;
}

struct SolveStatus {
  unsigned shots = 0;
  double convergence = 0;  // docs/design.md#convergence: 1 - sum |dB| A / sum E A (luminance)
  bool done = false;       // the stop rule fired
};

// Milliseconds spent per pass, summed over the run (GPU time for GPU passes).
struct PassTimings {
  double itemBuffer = 0, gather = 0, select = 0, readback = 0;
};

// Totals over all `passes` from the summed times of the `timed` ones (GPU stamps time a sample
// of the passes): select, item buffer, then gather (or update), as the timer's slots 0, 1, 2.
inline void scaleSampledTimings(PassTimings& t, const double (&sampled)[3], unsigned passes, unsigned timed) {
  const double scale = timed ? double(passes) / timed : 0.0;
  t.select = sampled[0] * scale;
  t.itemBuffer = sampled[1] * scale;
  t.gather = sampled[2] * scale;
}

struct StopRule {
  unsigned maxShots = 0;         // 0: no limit
  double targetConvergence = 0;  // 0: none
};

// Shots per advance(): batches grow while one takes under ~50 ms, so the status readback (the
// only CPU-GPU sync) stays rare on fast GPUs and progress stays live on slow ones.
inline unsigned nextBatch(unsigned batch, double seconds) {
  return seconds < 0.05 ? (batch < 512 ? batch * 2 : 1024) : (batch > 1 ? batch / 2 : 1);
}

class Solver;

// Batches of shots while the stop rule has not fired and `more()` holds (asked before each
// batch), sized by nextBatch from `batch`, which is left for the caller's next call. Batch
// sizes never change the result, only how often the status is read.
template <class More>
SolveStatus advanceWhile(Solver& solver, SolveStatus status, unsigned& batch, More more);
// Batches until the stop rule fires, running ahead of the status readback (advanceAhead), calling
// `afterBatch(status)` after each batch (a progress bar).
template <class AfterBatch>
SolveStatus advanceToStop(Solver& solver, SolveStatus status, AfterBatch afterBatch);
SolveStatus advanceToStop(Solver& solver, SolveStatus status);

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string algorithm() const = 0;
  // Runs up to `shots` more shots, fewer if the stop rule fires, and reports the state after.
  virtual SolveStatus advance(unsigned shots) = 0;
  // advance() for runs to the stop rule: the status it returns may be a batch behind (a GPU
  // solver reads the status of the passes before while the GPU runs the ones after), and
  // settle() returns the status after everything enqueued. Passes after the stop rule fired are
  // empty, so the result is advance()'s, bit for bit.
  virtual SolveStatus advanceAhead(unsigned shots) { return advance(shots); }
  virtual SolveStatus settle(SolveStatus last) { return last; }
  virtual const PassTimings& timings() const = 0;
  // Convergence after 0, 1, 2, ... shots.
  virtual std::vector<float> convergenceHistory() const = 0;
  // The algorithm's own state beyond B and dB (shot count, history, ...), for checkpoints:
  // restoreState() on a solver built with the same settings continues bitwise where the saved
  // one stood. The stop rule is this solver's, so a resumed solve may be given a new one.
  virtual std::vector<std::uint8_t> saveState() const = 0;
  virtual SolveStatus restoreState(std::span<const std::uint8_t> bytes) = 0;
};

template <class More>
SolveStatus advanceWhile(Solver& solver, SolveStatus status, unsigned& batch, More more) {
  while (!status.done && more()) {
    const auto t0 = std::chrono::steady_clock::now();
    status = solver.advance(batch);
    batch = nextBatch(batch, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return status;
}

template <class AfterBatch>
SolveStatus advanceToStop(Solver& solver, SolveStatus status, AfterBatch afterBatch) {
  unsigned batch = 1;
  while (!status.done) {
    const auto t0 = std::chrono::steady_clock::now();
    status = solver.advanceAhead(batch);
    batch = nextBatch(batch, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    afterBatch(status);
  }
  return solver.settle(status);
}

inline SolveStatus advanceToStop(Solver& solver, SolveStatus status) {
  return advanceToStop(solver, status, [](const SolveStatus&) {});
}

}  // namespace hemirad
