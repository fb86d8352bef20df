// A radiosity method (`solve --method NAME`) as one unit (issue 27): its name, the flags it
// takes bound into its own settings, how it solves, what a checkpoint of it must match and how
// it describes its run. Adding a method is a folder under src/method/ and a line in
// src/method/Registry.cpp; the contract tests (tests/MethodContractTest.cpp) then run over it.
#pragma once
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace hemirad {

struct SolveOptions;
struct RunInfo;
struct SolveStatus;
struct StopRule;
class Solver;
class SolverState;
class Scene;
class Atlas;
struct Camera;

// A flag of `solve` a method takes. `bind` stores the parsed value into the method's own
// settings and runs only when the flag was given; without it the flag is solve's own
// (SolveOptions) and the method merely accepts it. Solve declares each flag once, for all methods.
struct MethodFlag {
  std::string name;                              // "--item-res"
  std::function<void(const CLI::Option&)> bind;  // empty: accepted, stored by solve itself
  std::string defaultText;                       // shown as its default in --help and docs/cli.md
  std::string value;                             // the field's initial value, shown without defaultText
};

// How the contract tests (tests/MethodContractTest.cpp) solve scenes/analytic/furnace.obj, a
// closed box of walls emitting E 1 with rho 0.5 seen from inside: the flags, and the mean B its
// camera image must show (E / (1 - rho) = 2 for a method that carries every bounce) within a
// relative tolerance the method's own error allows.
struct ClosedBoxRun {
  std::string flags;
  double expected = 2;
  double tolerance = 0;
};

class MethodUnit {
 public:
  virtual ~MethodUnit() = default;
  virtual std::string name() const = 0;
  // The flags it takes, bound into this object's settings; any other method flag is refused.
  virtual std::vector<MethodFlag> flags() = 0;
  // After binding, before any work: InputError for what this method cannot do with `o`.
  virtual void settle(const SolveOptions& o) = 0;
  // After settle: whether its camera image is exact (--image-plan, exactImagesFor): solve's auto
  // --discontinuities and --supersample follow it (docs/solve.md#exact-images).
  virtual bool exactImages() const { return false; }
  // The solve, from the scene to the files; 128 + a signal when one stopped it.
  virtual int solve(const SolveOptions& o) const = 0;
  // Whether --checkpoint and --resume mean something to it.
  virtual bool checkpoints() const = 0;
  // Flags for a small, quick solve (a few hundred elements or pixels): the contract tests' runs.
  virtual std::string quickFlags() const = 0;
  virtual ClosedBoxRun closedBox() const = 0;
};

// One solve of an atlas method: its Solver over the state, and what only this method knows of it.
class AtlasRun {
 public:
  virtual ~AtlasRun() = default;
  virtual Solver& solver() = 0;
  // Before the first batch (after a restore): the camera, for methods driven by the view.
  virtual void look(const Camera& camera, double aspect) = 0;
  // Whether camera images add seed 004's ambient term for light not yet shot (dB).
  virtual bool ambient() const = 0;
  // The report's fields this method fills (item buffer, shots of each kind, ...).
  virtual void describe(RunInfo& run) const = 0;
  // `--direct per-pixel`: B of the emitters' light alone, per element (src/solver/DirectSplit.h),
  // so camera images compute direct light per pixel and take only the rest from the solution.
  // Empty (the default, `--direct atlas`): images show B.
  virtual std::vector<glm::vec4> directOnly(const Camera&, double /*aspect*/) const { return {}; }
  // `--final-gather near`: camera images regather the near field per pixel (src/output/NearGather.h).
  virtual bool nearGather() const { return false; }
  // How far the solve got, for the summary line.
  virtual std::string reached(const SolveStatus& status) const = 0;
  // A walkthrough along o.cameraPath instead of one image (only methods that accept --camera-path).
  virtual int walkthrough(const SolveOptions& o, const Scene& scene, const Atlas& atlas, SolverState& state,
                          const Camera& camera) = 0;
};

// A method that solves for radiosity per atlas element with a Solver: src/cli/Solve.cpp runs
// it (outputs, checkpoints, signals, report), the method supplies the solver and its account.
class AtlasMethod : public MethodUnit {
 public:
  int solve(const SolveOptions& o) const override;  // src/cli/Solve.cpp
  bool checkpoints() const override { return true; }
  virtual std::unique_ptr<AtlasRun> start(SolverState& state) const = 0;
  // An adaptive round's solve (src/cli/AdaptiveRounds.h), which only has to show where the light
  // is steep: a method whose stop rule is a convergence stops it at roundStop's.
  virtual std::unique_ptr<AtlasRun> startRound(SolverState& state) const { return start(state); }
  // Its parameters a checkpoint must have been made with (beside the scene and atlas).
  virtual nlohmann::json identity() const = 0;
  virtual const StopRule& stop() const = 0;
  // The camera image's per-pixel refinements in effect ("per-pixel direct light", ...), for the
  // line that announces an exact image.
  virtual std::vector<std::string> pixelRefinements() const { return {}; }
};

}  // namespace hemirad
