// Progressive-refinement radiosity on the GPU (seed 003): per pass, a reduction picks the
// blocks with the largest unshot power (one, or several: seed 003's batching), the item mesh
// is rasterised into a hemispherical item buffer from each, and a compute pass gathers their
// shots into every receiver texel. The choice and the stop rule stay on the GPU: the CPU only
// enqueues passes and reads a small status block between batches of them.
#pragma once
#include <memory>

#include "gl/Objects.h"
#include "gl/Readback.h"
#include "gl/Shader.h"
#include "gl/Timer.h"
#include "src/scene/Camera.h"
#include "src/solver/BvhBuffers.h"
#include "src/solver/HostTrace.h"
#include "src/solver/ImportanceView.h"
#include "src/solver/ItemBuffer.h"
#include "src/solver/PerspectiveView.h"
#include "src/solver/Presets.h"
#include "src/solver/ShooterTree.h"
#include "src/solver/ShootingPlan.h"
#include "src/solver/Solver.h"
#include "src/solver/SolverState.h"

namespace hemirad {

// How the gather decides whether a receiver sees a shooter's origin (docs/design.md#visibility).
enum class Visibility {
  Auto,        // resolveVisibility: bvh on scenes of many triangles, unless an item buffer is asked for
  ItemBuffer,  // seed 003: the shooter's item buffer nominates occluders, exact segment tests decide
  Bvh,         // exact segment tests through the scene's BVH; no item buffer is drawn
};

// Where --visibility bvh's segments are traced: by the gather's GLSL walk, or on the host by
// Embree (HostTrace.h), which a CPU device (llvmpipe) does 20-30x sooner. Tests ask for each.
enum class HostTraceUse { OnCpuDevice, Always, Never };

inline const char* visibilityName(Visibility v) {
  return v == Visibility::Bvh ? "bvh" : v == Visibility::ItemBuffer ? "item-buffer" : "auto";
}
// What Auto becomes: an item buffer costs a shot its triangles, the BVH each receiver a walk of
// log(triangles) boxes, so past as many scene triangles as elements the walk is the cheaper
// (measured on llvmpipe and the H200: docs/real-scenes.md#visibility-through-the-bvh). But a
// particular item buffer asked for (a projection, item-mesh level or resolution other than the
// fast plan's: seed 003's, the reference's, an artifact study's) is drawn.
inline Visibility resolveVisibility(Visibility v, std::size_t triangles, std::size_t elements, bool plannedItemBuffer) {
  if (v != Visibility::Auto) return v;
  return plannedItemBuffer && triangles >= elements ? Visibility::Bvh : Visibility::ItemBuffer;
}

struct ProgressiveSettings {
  // The item buffer and shooters start as the default preset's, `fast` (src/solver/Presets.h).
  int itemSubdivision = kFastPlan.itemSubdivision;  // 1-to-4 splits of the item mesh
  int itemResolution =
      kFastPlan
          .itemResolution;  // item buffer pixels per side (the hemicube's budget too); kAutoItemResolution: planned
  Projection projection = kFastPlan.projection;
  int shootLevel = kFastPlan.shootLevel;  // substructuring: shoot from 2^k x 2^k texel blocks; kAutoShootLevel: planned
  double refineNear = kFastPlan.refineNear;  // receivers nearer than this many shooter sides see its parts (0: off;
                                             // kAutoRefineNear: refineNearFor the stop rule, nearRefinement())
  std::string preset{kDefaultPreset};        // the preset the five above started from (the report names it)
  Visibility visibility = Visibility::Auto;
  HostTraceUse hostTrace = HostTraceUse::OnCpuDevice;  // who traces --visibility bvh's segments
  bool nearGather = false;  // --final-gather near: images regather their near field; auto refines further
  ItemPlan plan() const { return {projection, itemSubdivision, itemResolution, shootLevel, refineNear}; }
  // Starts from preset `name` (InputError for an unknown name): its five values and its name.
  void usePreset(std::string_view name) {
    const Preset& p = findPreset(name);
    preset = std::string(p.name);
    projection = p.plan.projection, itemSubdivision = p.plan.itemSubdivision;
    itemResolution = p.plan.itemResolution, shootLevel = p.plan.shootLevel, refineNear = p.plan.refineNear;
  }
  std::string presetLabel() const { return hemirad::presetLabel(preset, plan()); }
  // The near-shooter refinement this solve runs with: refineNear, auto resolved by the stop rule
  // and the images' near gather.
  double nearRefinement() const { return refineNearFor(refineNear, stop.targetConvergence, nearGather); }
  // A block whose elements' unshot radiosity spans more than uniformRatio (least / largest
  // luminance) shoots its brightest quadrant, down to splitDepth levels (ShooterTree.h).
  // Depth 3 and 0.1: within 1 % of per-element shooting on the Cornell box's objects with
  // --shoot-level auto, for 35 % more shots (docs/bench/h200-2026-12-02.md).
  int splitDepth = 3;
  double uniformRatio = 0.1;
  // Shooters per pass (1..kMaxPassShooters): the best K blocks shoot at once from the same
  // unshot state, so a pass's fixed costs (reduction, launches, barriers) are shared by K shots.
  // 16: the fastest on the H100 and llvmpipe at 10k elements (docs/bench), 1 % more shots.
  int shootersPerPass = 16;
  // Importance-driven shooting (seed 004 §4.2, `--algorithm importance`): each pass also
  // shoots importance from as many blocks, and radiosity shooters are ranked by unshot power x
  // (largest received importance I - R in the block + importanceFloor / total area). The floor
  // lets power nobody looks at be shot in the end, so the solve still converges everywhere.
  Algorithm algorithm = Algorithm::Progressive;
  double importanceFloor = 0.01;
  bool importanceDriven() const { return algorithm != Algorithm::Progressive; }
  // Perspective-driven shooting (seed 004 §5): after each camera move the simulated field of
  // view grows to the whole scene over this many shots (0: a quarter of the scene's shooter
  // blocks, at least 8 passes). The thesis counted seconds; shots keep runs reproducible.
  unsigned fovDecayShots = 0;
  // Perspective-driven: surfaces whose received importance I - R exceeds viewInterest / (total area) (1: the
  // view's importance spread evenly) are in the area of interest too, in view or not, so the
  // light that reaches the view through surfaces out of it is not held back (issue 19: without
  // it the ceiling over the camera lit nothing). 0: the simulated field of view only (the thesis).
  double viewInterest = 1.0;
  // Per-pass times: GPU stamps on a sample of the passes, every shot synchronised, or none.
  gl::TimerMode timings = gl::TimerMode::Gpu;
  StopRule stop;
  // Receivers keep received light in B only: the emitters alone shoot (src/solver/DirectSplit.h).
  bool directOnly = false;
};

class ProgressiveSolver final : public Solver {
 public:
  ProgressiveSolver(SolverState& state, const ProgressiveSettings& settings);
  ~ProgressiveSolver() override;
  std::string algorithm() const override { return algorithmName(settings_.algorithm); }
  // Importance-driven solves: the user's view (aspect width / height) that drives them, again
  // whenever it moves; the importance already shot is corrected by the difference.
  void look(const Camera& camera, double aspect);
  bool viewDriven() const { return view_ != nullptr; }
  unsigned importanceShots() const { return importanceShots_; }
  // Perspective-driven solves: item buffers rendered to hand stored entries to surfaces entering
  // the view, and the area of interest now.
  unsigned deliveryShots() const { return deliveryShots_; }
  unsigned fovDecayShots() const { return perspective_ ? perspective_->decayShots() : 0; }
  const PerspectiveView* perspective() const { return perspective_.get(); }
  std::vector<float> directImportance() const { return view_ ? view_->readDirect() : std::vector<float>{}; }
  // Runs passes of up to shootersPerPass shots until `shots` more have been enqueued.
  SolveStatus advance(unsigned shots) override;
  SolveStatus advanceAhead(unsigned shots) override;
  SolveStatus settle(SolveStatus last) override;
  const PassTimings& timings() const override { return timings_; }
  std::vector<float> convergenceHistory() const override;
  std::vector<std::uint8_t> saveState() const override;  // the control block's status and history
  SolveStatus restoreState(std::span<const std::uint8_t> bytes) override;
  Visibility visibility() const { return visibility_; }  // as resolved (never Auto)
  // Triangles and pixels one shooter's item buffer draws (0 with --visibility bvh: none is drawn).
  std::size_t itemTriangles() const { return itemBuffer_ ? itemBuffer_->triangles() : 0; }
  std::size_t itemPixels() const { return itemBuffer_ ? itemBuffer_->pixelsPerShooter() : 0; }
  std::size_t shooterBlocks() const { return blockCount_; }
  // Shooter-tree nodes whose shape is past the piece budget (kMaxShapePieces): the disc form factor.
  std::size_t discShapes() const { return discShapes_; }
  const ShootingPlan& plan() const { return plan_; }

 private:
  // What a ranking orders the blocks by (reduce_entry.glsl's rankBy).
  enum class Rank : unsigned {
    Power = 0,              // unshot power: plain progressive refinement
    PowerByImportance = 1,  // unshot power x (largest I - R + floor), seed 004 §4.2.4
    Importance = 2,         // |unshot importance| x area: the importance shooters
  };
  // Who receives a gather (gather.comp's viewMode; perspective-driven solves only).
  enum class Receivers : unsigned {
    InView = 1,    // a shot: only surfaces in the area of interest
    Entering = 2,  // a delivery: only surfaces entering the view, each its stored entry
  };

  void setUpTree(const std::vector<ShooterBlock>& blocks, const gl::Defines& defines);
  void setUpReduction(unsigned keep, const gl::Defines& defines);
  void setUpControl(const StopRule& stop, unsigned keep);
  bool refinesNear() const { return settings_.nearRefinement() > 0 && treeDepth_ > 0; }
  bool tracesBvh() const { return refinesNear() || visibility_ == Visibility::Bvh; }
  void setUpBvh(gl::Defines& gatherDefines, std::span<const std::uint32_t> receivers, bool viewDriven);
  void preparePassVisibility();                  // the pass's item buffers, or the host's traced answers (else none)
  void selectPass(bool importanceOnly = false);  // the stats, then the rankings and choices
  void rankPass(Rank rank, bool importanceShooters);
  void gatherPass(Receivers receivers);
  void importancePass();  // importance shooters only: the view's importance one shot further
  void runPasses(unsigned passes);
  // Perspective-driven: item buffers for deliveries and for shots share `budget`.
  void advancePerspective(unsigned budget);
  unsigned deliverStored();                   // one pass of entries for surfaces entering the view
  bool openWholeView();                       // out of light with entries held back
  unsigned shootToNextStep(unsigned budget);  // returns the shots enqueued
  bool budgetSpent() const { return settings_.stop.maxShots && status_.shots >= settings_.stop.maxShots; }
  SolveStatus readStatus();  // after every pass enqueued so far
  // The oldest pending status copy; the pass timings' stamps read so far, or with
  // `waitForStamps` all of them (until then timings() is short by the timed passes in flight).
  SolveStatus collectStatus(bool waitForStamps);

  SolverState& state_;
  ProgressiveSettings settings_;
  ShootingPlan plan_;
  // node_stats.comp, once per workgroup size (statsThreads): the program and its blocks.
  struct StatsGroup {
    gl::Program program;
    gl::Buffer blocks;
    unsigned count = 0;
  };
  std::vector<StatsGroup> stats_;
  gl::Program reduce_, select_, gather_;
  gl::Buffer nodes_, nodeStats_, control_;  // the shooter tree, its per-pass sums (ShooterTree.h)
  gl::Readback statusCopies_;               // the control block's status header, read back
  std::size_t discShapes_ = 0;
  gl::Buffer shapes_;     // per node: its exact shape (shapeTable), what the gather integrates over
  int treeDepth_ = 0;     // levels below the deepest block
  BvhBuffers bvh_;        // the scene's BVH: exact visibility (near shooters, or --visibility bvh)
  gl::Buffer receivers_;  // the gather's receiver texels in visiting order (ReceiverOrder.h)
  unsigned receiverCount_ = 0;
  std::unique_ptr<HostTrace> hostTrace_;  // a CPU device's traced visibility (HostTrace.h)
  gl::Buffer hostVisible_;                // its answers for the pass, SSBO_HOST_VISIBLE
  std::vector<std::uint32_t> hostBits_;
  Visibility visibility_;
  std::unique_ptr<ItemBuffer> itemBuffer_;        // none with --visibility bvh
  std::unique_ptr<ImportanceView> view_;          // importance-driven solves only
  std::unique_ptr<PerspectiveView> perspective_;  // perspective-driven solves only
  unsigned importanceShots_ = 0, deliveryShots_ = 0;
  std::vector<gl::Buffer> levels_;  // outputs of the parallel reduction levels (large scenes)
  std::size_t blockCount_ = 0;
  unsigned historyCapacity_ = 0;
  SolveStatus status_;
  PassTimings timings_;
  gl::GpuTimer timer_;
  double sampled_[3] = {};             // per-pass milliseconds of the timed passes
  unsigned enqueued_ = 0, timed_ = 0;  // passes
};

}  // namespace hemirad
