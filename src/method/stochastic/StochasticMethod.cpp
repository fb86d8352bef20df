// --method stochastic: stochastic iteration (seed 000), --shots iterations of K random texel
// shooters. It has no convergence to stop at and nothing unshot for an ambient term.
#include <fmt/format.h>

#include <stdexcept>

#include "src/base/Error.h"
#include "src/cli/Solve.h"
#include "src/method/MethodFlag.h"
#include "src/output/Report.h"
#include "src/solver/Projection.h"
#include "src/solver/StochasticSolver.h"

namespace hemirad {

namespace {

class StochasticRun final : public AtlasRun {
 public:
  StochasticRun(SolverState& state, const StochasticSettings& settings)
      : settings_(settings), solver_(state, settings) {}
  Solver& solver() override { return solver_; }
  void look(const Camera&, double) override {}
  // The ambient term stands in for light not yet shot (dB); stochastic iteration keeps its
  // iterate there instead, and its running mean already holds every bounce.
  bool ambient() const override { return false; }
  void describe(RunInfo& run) const override {
    run.itemSubdivision = settings_.itemSubdivision;
    run.itemResolution = solver_.itemResolution();
    run.itemTriangles = solver_.itemTriangles();
    run.shootLevel = 0;  // one-texel shooters
    run.shootersPerPass = settings_.shooters;
  }
  std::string reached(const SolveStatus& status) const override {
    return fmt::format("{} iterations of {} shooters", status.shots, settings_.shooters);
  }
  int walkthrough(const SolveOptions&, const Scene&, const Atlas&, SolverState&, const Camera&) override {
    throw std::logic_error("--camera-path is progressive refinement's");  // refused when the flags were bound
  }

 private:
  const StochasticSettings& settings_;
  StochasticSolver solver_;
};

// solve's stochastic iteration takes progressive refinement's item buffer, 512^2 (bench,
// compare-methods and animate keep StochasticSettings' 256^2).
StochasticSettings stochasticSolveDefaults() {
  StochasticSettings s;
  s.itemResolution = 512;
  return s;
}

class StochasticMethod final : public AtlasMethod {
 public:
  std::string name() const override { return "stochastic"; }
  std::vector<MethodFlag> flags() override {
    StochasticSettings& s = settings_;
    return {bindFlag("--shots", s.stop.maxShots),
            bindFlag("--item-subdiv", s.itemSubdivision),
            bindFlag("--item-res", s.itemResolution),
            projectionFlag(s.projection),
            bindFlag("--shooters-per-pass", s.shooters),
            bindFlag("--seed", s.seed),
            parseFlag("--transport", s.source, parseSource, "iterate"),
            switchFlag("--sync-timings", [&s] { s.timings = gl::TimerMode::Synchronous; })};
  }
  void settle(const SolveOptions&) override {
    if (!settings_.stop.maxShots)
      throw InputError("--method stochastic needs --shots N (iterations): it has no convergence to stop at");
  }
  std::string quickFlags() const override { return "--elements 300 --item-res 64 --item-subdiv 1 --seed 5"; }
  // B is the mean of 256 iterates: its noise (about 0.3 % here; tests/StochasticGLTest.cpp measures
  // the standard error) and the start's bias (at most 2 / 256 of B / 2, 0.4 %) stay within 1 %.
  ClosedBoxRun closedBox() const override {
    return {"--elements 300 --shots 256 --shooters-per-pass 8 --item-res 64", 2, 0.01};
  }
  std::unique_ptr<AtlasRun> start(SolverState& state) const override {
    return std::make_unique<StochasticRun>(state, settings_);
  }
  // shoot_level: progressive refinement's default, as checkpoints written before issue 27 hold.
  nlohmann::json identity() const override {
    const StochasticSettings& s = settings_;
    return {{"item_subdivision", s.itemSubdivision},
            {"item_resolution", s.itemResolution},
            {"projection", projectionName(s.projection)},
            {"shoot_level", 1},
            {"shooters_per_pass", s.shooters},
            {"seed", s.seed},
            {"transport", sourceName(s.source)}};
  }
  const StopRule& stop() const override { return settings_.stop; }

 private:
  StochasticSettings settings_ = stochasticSolveDefaults();
};

}  // namespace

std::unique_ptr<MethodUnit> makeStochasticMethod() { return std::make_unique<StochasticMethod>(); }

}  // namespace hemirad
