// --method progressive: progressive refinement (seed 003) and its view-driven algorithms
// (seed 004), the only method with a convergence to stop at and walkthroughs.
#include <fmt/format.h>

#include <optional>
#include <utility>

#include "src/base/Error.h"
#include "src/cli/Solve.h"
#include "src/method/MethodFlag.h"
#include "src/output/ImageFile.h"
#include "src/output/Report.h"
#include "src/solver/DirectSplit.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/Projection.h"
#include "src/solver/Subdivide.h"
#include "src/walk/CameraPath.h"
#include "src/walk/Walkthrough.h"

namespace hemirad {

namespace {

class ProgressiveRun final : public AtlasRun {
 public:
  ProgressiveRun(SolverState& state, const ProgressiveSettings& settings, bool perPixelDirect)
      : settings_(settings), solver_(state, settings), state_(state), perPixelDirect_(perPixelDirect) {}
  Solver& solver() override { return solver_; }
  void look(const Camera& camera, double aspect) override {
    if (settings_.importanceDriven()) solver_.look(camera, aspect);
  }
  bool ambient() const override { return true; }
  // The item buffer is the one the solver used (planned with auto), the shoot level as given.
  void describe(RunInfo& run) const override {
    run.preset = settings_.presetLabel();
    run.projection = projectionName(settings_.projection);
    run.itemSubdivision = settings_.itemSubdivision;
    run.itemResolution = solver_.plan().itemResolution;
    run.shootLevel = settings_.shootLevel;
    run.shooterBlocks = solver_.shooterBlocks();
    run.refineNear = settings_.nearRefinement();
    run.visibility = visibilityName(solver_.visibility());
    run.shootersPerPass = settings_.shootersPerPass;
    run.importanceShots = solver_.importanceShots();
    run.deliveryShots = solver_.deliveryShots();
    run.fovDecayShots = solver_.fovDecayShots();
    run.itemTriangles = solver_.itemTriangles();
    run.discShapes = solver_.discShapes();
    run.direct = perPixelDirect_ ? "per-pixel" : "atlas";
    run.finalGather = settings_.nearGather ? "near" : "off";
  }
  std::vector<glm::vec4> directOnly(const Camera& camera, double aspect) const override {
    if (!perPixelDirect_) return {};
    return directOnlyRadiosity(state_.scene, state_.atlas, settings_, camera, aspect);
  }
  bool nearGather() const override { return settings_.nearGather; }
  std::string reached(const SolveStatus& status) const override {
    return fmt::format("{} shots, convergence {:.4f}", status.shots, status.convergence);
  }
  int walkthrough(const SolveOptions& o, const Scene& scene, const Atlas& atlas, SolverState& state,
                  const Camera& camera) override;

 private:
  const ProgressiveSettings settings_;  // its own: startRound hands it settings made for the round
  ProgressiveSolver solver_;
  const SolverState& state_;
  bool perPixelDirect_;
};

int ProgressiveRun::walkthrough(const SolveOptions& o, const Scene& scene, const Atlas& atlas, SolverState& state,
                                const Camera& camera) {
  const CameraPath path = readCameraPath(o.cameraPath, camera, scene.unitScale);
  WalkthroughOptions w = o.walkthrough;
  w.width = o.width, w.height = o.height, w.supersample = o.supersample, w.ambient = o.ambient.value_or(true),
  w.exposure = o.exposure;
  w.writeFrame = writePng;
  w.progress = o.progress;
  ConvergedViews converged(scene, atlas, settings_, o.referenceConvergence, o.progress);
  const std::vector<FrameRecord> frames = walk(solver_, state, path, converged, w);
  writeFramesCsv(w.framesDir + "/frames.csv", frames);
  const FrameRecord& last = frames.back();
  fmt::print(stderr,
             "hemirad: {}: {} frames along {} ({} shots, visible convergence {:.4f}, image error {:.4f}) into {}\n",
             o.scene, frames.size(), o.cameraPath, last.shots, last.visibleConvergence, last.imageError, w.framesDir);
  return 0;
}

// --direct, --final-gather: `on` ("per-pixel", "near") true, the other value false, auto unset.
auto autoOrGiven(const char* on) {
  return [on](const std::string& v) { return v == "auto" ? std::optional<bool>() : std::optional<bool>(v == on); };
}

class ProgressiveMethod final : public AtlasMethod {
 public:
  std::string name() const override { return "progressive"; }
  std::vector<MethodFlag> flags() override {
    ProgressiveSettings& p = settings_;
    // --preset first: choose() binds in this order, so the flags given beside it override it.
    return {parseFlag(
                "--preset", p.preset, [&p](const std::string& name) { return p.usePreset(name), p.preset; },
                std::string(kDefaultPreset)),
            bindFlag("--converge", p.stop.targetConvergence, "0.9; 0.9999 with --camera-path"),
            bindFlag("--shots", p.stop.maxShots),
            bindFlag("--item-subdiv", p.itemSubdivision, options::defaultText("--item-subdiv")),
            bindFlag("--item-res", p.itemResolution, options::defaultText("--item-res")),
            projectionFlag(p.projection),
            bindFlag("--shoot-level", p.shootLevel, options::defaultText("--shoot-level")),
            bindFlag("--refine-near", p.refineNear, options::defaultText("--refine-near")),
            bindFlag("--visibility", p.visibility),
            bindFlag("--algorithm", p.algorithm),
            bindFlag("--fov-decay", p.fovDecayShots),
            bindFlag("--shooters-per-pass", p.shootersPerPass),
            parseFlag("--direct", direct_, autoOrGiven("per-pixel"), "auto"),
            parseFlag("--final-gather", gather_, autoOrGiven("near"), "auto"),
            switchFlag("--sync-timings", [&p] { p.timings = gl::TimerMode::Synchronous; }),
            acceptFlag("--camera-path")};
  }
  // A walkthrough shoots until its path ends; a single solve stops at 0.9 unless told. The image
  // plan (docs/solve.md#exact-images) sets what --direct and --final-gather leave auto.
  void settle(const SolveOptions& o) override {
    StopRule& stop = settings_.stop;
    if (!stop.maxShots && !stop.targetConvergence) stop.targetConvergence = o.cameraPath.empty() ? 0.9 : 0.9999;
    if (!o.cameraPath.empty())
      for (auto [flag, on] : {std::pair{"--direct per-pixel", direct_.value_or(false)},
                              {"--final-gather near", gather_.value_or(false)},
                              {"--image-plan exact", o.imagePlan == ImagePlan::Exact}})
        if (on)
          throw InputError(fmt::format("{} renders one solve's --out and --image, not --camera-path frames", flag));
    if (gather_.value_or(false) && !direct_.value_or(true))
      throw InputError("--final-gather near adds to per-pixel direct light: it cannot take --direct atlas");
    exactImages_ = exactImagesFor(o.imagePlan, stop.targetConvergence, o.cameraImage(), o.gpu);
    perPixelDirect_ = direct_.value_or(exactImages_ || gather_.value_or(false));
    settings_.nearGather = gather_.value_or(exactImages_ && perPixelDirect_);
  }
  bool exactImages() const override { return exactImages_; }
  std::vector<std::string> pixelRefinements() const override {
    std::vector<std::string> parts;
    if (perPixelDirect_) parts.emplace_back("per-pixel direct light");
    if (settings_.nearGather) parts.emplace_back("the near final gather");
    return parts;
  }
  std::string quickFlags() const override { return "--elements 300 --item-res 64 --item-subdiv 1"; }
  // What is left unshot at 0.9995 lowers B by < 0.05 %; exact form factors lose < 0.05 % more.
  ClosedBoxRun closedBox() const override { return {"--elements 300 --converge 0.9995", 2, 0.001}; }
  std::unique_ptr<AtlasRun> start(SolverState& state) const override {
    return std::make_unique<ProgressiveRun>(state, settings_, perPixelDirect_);
  }
  std::unique_ptr<AtlasRun> startRound(SolverState& state) const override {
    ProgressiveSettings round = settings_;
    round.stop = roundStop(settings_.stop);
    return std::make_unique<ProgressiveRun>(state, round, perPixelDirect_);
  }
  nlohmann::json identity() const override {
    const ProgressiveSettings& p = settings_;
    nlohmann::json identity = {{"item_subdivision", p.itemSubdivision},
                               {"item_resolution", p.itemResolution},
                               {"projection", projectionName(p.projection)},
                               {"shoot_level", p.shootLevel},
                               {"refine_near", p.nearRefinement()},
                               {"shooters_per_pass", p.shootersPerPass}};
    if (p.algorithm == Algorithm::Perspective) identity["fov_decay"] = p.fovDecayShots;  // 0: the default
    if (p.visibility != Visibility::Auto) identity["visibility"] = visibilityName(p.visibility);
    return identity;
  }
  const StopRule& stop() const override { return settings_.stop; }

 private:
  ProgressiveSettings settings_;
  std::optional<bool> direct_, gather_;  // --direct, --final-gather as given
  bool perPixelDirect_ = false;          // camera images only, so not in identity()
  bool exactImages_ = false;
};

}  // namespace

std::unique_ptr<MethodUnit> makeProgressiveMethod() { return std::make_unique<ProgressiveMethod>(); }

}  // namespace hemirad
