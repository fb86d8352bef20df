#include "src/solver/ProgressiveSolver.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstddef>
#include <cstring>
#include <map>

#include <fmt/format.h>

#include "gl/Backend.h"
#include "gl/Debug.h"
#include "gl/Limits.h"
#include "gl/State.h"
#include "src/base/Error.h"
#include "src/scene/ItemMesh.h"
#include "src/solver/Bvh.h"
#include "src/solver/Control.h"
#include "src/solver/HostTrace.h"
#include "src/solver/ReceiverOrder.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {

// gather.comp's local size: 64 (then 8 x 8 atlas texels) fills the H200's 132
// SMs better than 256 at 100k elements (a pass's gather 138 -> 123 us; the same at 10k;
// docs/bench/h200-2026-12-04f.md).
constexpr unsigned kGatherGroup = 64;
constexpr unsigned kGroupEntries = 1024;  // entries ranked per reduction workgroup (reduce_entry.glsl)
constexpr unsigned kUnlimitedHistory = 1u << 20;
// Passes enqueued past the status a run to the stop rule reads (advanceAhead): with 2, the H200's
// Cornell box to 90 % at 100k elements took 16.2 ms against 20.4 reading after every batch, 10k
// the same (6.8 against 6.7 ms; docs/bench/h200-2026-12-05.md); larger chunks only add empty
// passes after the stop.
constexpr unsigned kAheadPasses = 2;

enum Slot { kSelect, kItemBuffer, kGather };

constexpr gl::Barrier kAllBarriers = gl::Barrier::Storage | gl::Barrier::Image | gl::Barrier::TextureFetch;

// A quarter of the blocks: solves reach 90 % in about half as many shots as there are blocks,
// so the view opens up over the first third or so of that, as the thesis's 10 s of ~30 s did.
unsigned defaultFovDecay(std::size_t blocks, unsigned shootersPerPass) {
  return std::max(unsigned(blocks / 4), 8u * shootersPerPass);
}

}  // namespace

ProgressiveSolver::ProgressiveSolver(SolverState& state, const ProgressiveSettings& settings)
    : state_(state), settings_(settings), timer_(gl::contextTimerMode(settings.timings)) {
  if (settings.shootersPerPass < 1 || unsigned(settings.shootersPerPass) > kMaxPassShooters)
    throw InputError(
        fmt::format("--shooters-per-pass must be 1 to {}, not {}", kMaxPassShooters, settings.shootersPerPass));
  const unsigned keep = unsigned(settings.shootersPerPass);
  const bool perspective = settings.algorithm == Algorithm::Perspective;
  const gl::Defines defines = perspective ? gl::Defines{{"PERSPECTIVE", "1"}} : gl::Defines{};
  plan_ = planShooting(state.scene, state.atlas, settings.shootLevel, settings.itemResolution, settings.projection,
                       settings.nearRefinement());
  setUpTree(state.atlas.shooterBlocks(plan_.chartLevel), defines);
  setUpReduction(keep, defines);

  // Item-buffer layers: K radiosity shooters, and K importance shooters after them.
  const bool plannedItemBuffer = settings.projection == kFastPlan.projection &&
                                 settings.itemSubdivision == kFastPlan.itemSubdivision &&
                                 settings.itemResolution == kFastPlan.itemResolution;
  visibility_ = resolveVisibility(settings.visibility, itemTriangleCount(state.scene, 0), state.atlas.elements,
                                  plannedItemBuffer);
  if (visibility_ == Visibility::ItemBuffer)
    itemBuffer_ = std::make_unique<ItemBuffer>(state.scene, settings.itemSubdivision, plan_.itemResolution,
                                               state.farDistance, settings.projection,
                                               settings.shootersPerPass * (settings.importanceDriven() ? 2 : 1));
  if (settings.importanceDriven()) view_ = std::make_unique<ImportanceView>(state);
  gl::Defines gatherDefines = itemBufferDefines(settings.projection);
  gatherDefines.insert(gatherDefines.end(), defines.begin(), defines.end());
  const std::vector<std::uint32_t> order =
      receiverOrder(state.atlas, state.scene.boundsMin(), state.scene.boundsMax(), kGatherGroup);
  receivers_ = gl::Buffer(std::span<const std::uint32_t>(order));
  receiverCount_ = unsigned(order.size());
  setUpBvh(gatherDefines, order, settings.importanceDriven() || perspective);
  if (settings.directOnly) gatherDefines.push_back({"DIRECT_ONLY", "1"});
  gatherDefines.push_back({"GATHER_GROUP", std::to_string(kGatherGroup)});
  gather_ = computeProgram("gather.comp", gatherDefines);
  if (refinesNear()) gather_.set("refineNear", float(settings.nearRefinement()));
  if (perspective) {
    perspective_ = std::make_unique<PerspectiveView>(
        state, nodes_, blockCount_,
        settings.fovDecayShots ? settings.fovDecayShots : defaultFovDecay(blockCount_, keep), settings.viewInterest);
    gather_.set("blockCount", unsigned(blockCount_));
  }
  setUpControl(settings.stop, keep);
  gather_.set("farDistance", float(state.farDistance));
  gather_.set("receiverCount", receiverCount_);
  gl::checkErrors("progressive solver setup");
}

// The shooter blocks, their quadtrees (cut where unshot radiosity is not uniform), the nodes'
// exact shapes and the pass that sums each node's unshot state. node_stats.comp gives each block
// a workgroup of statsThreads(block) threads, one program per size: a thread per texel, 16-256.
void ProgressiveSolver::setUpTree(const std::vector<ShooterBlock>& blocks, const gl::Defines& defines) {
  const ShooterTree tree = buildShooterTree(state_.atlas, blocks, settings_.splitDepth);
  blockCount_ = tree.blocks;
  treeDepth_ = tree.depth;
  // The largest per-node table: refused before any upload when one storage block cannot hold it.
  gl::requireStorageBlock(tree.nodes.size() * kShapeStride * sizeof(glm::vec4),
                          fmt::format("the shapes of {} shooter-tree nodes", tree.nodes.size()));
  nodes_ = gl::Buffer(std::span<const ShooterNode>(tree.nodes));
  nodeStats_ = gl::Buffer(tree.nodes.size() * sizeof(glm::vec4[4]));
  std::vector<glm::ivec4> rects;
  for (const ShooterNode& n : tree.nodes) rects.push_back(n.rect);
  const ShapeTable shapes = shapeTable(state_.scene, state_.atlas, rects);
  gl::requireStorageBlock(shapes.slots.size() * sizeof(glm::vec4),
                          fmt::format("the shapes of {} shooter-tree nodes", tree.nodes.size()));
  discShapes_ = shapes.discShapes;
  shapes_ = gl::Buffer(std::span<const glm::vec4>(shapes.slots));
  std::map<unsigned, std::vector<std::uint32_t>> byThreads;
  for (std::size_t b = 0; b < tree.blocks; ++b) byThreads[statsThreads(tree, b)].push_back(std::uint32_t(b));
  for (const auto& [threads, list] : byThreads) {
    gl::Defines statsDefines = defines;
    statsDefines.push_back({"BLOCK_THREADS", std::to_string(threads)});
    if (settings_.importanceDriven()) statsDefines.push_back({"IMPORTANCE_DRIVEN", "1"});
    StatsGroup& g = stats_.emplace_back();
    g.program = computeProgram("node_stats.comp", statsDefines);
    g.blocks = gl::Buffer(std::span<const std::uint32_t>(list));
    g.count = unsigned(list.size());
    g.program.set("blockCount", g.count);
  }
}

// The reduction levels above the blocks: each workgroup of a level ranks 1024 entries and
// keeps its best `keep`, until select.comp's one workgroup can rank the rest.
void ProgressiveSolver::setUpReduction(unsigned keep, const gl::Defines& defines) {
  reduce_ = computeProgram("reduce.comp");
  select_ = computeProgram("select.comp", defines);
  unsigned left = unsigned(blockCount_);
  for (; left > kGroupEntries; left = gl::groupsFor(left, kGroupEntries) * keep)
    levels_.emplace_back(gl::groupsFor(left, kGroupEntries) * keep * sizeof(float[4]));
  // select.comp folds what the parallel levels leave: the blocks themselves when there are none.
  select_.set("count", left);
  select_.set("keep", keep);
  reduce_.set("keep", keep);
  select_.set("fromBlocks", int(levels_.empty()));
  // Importance is a view fraction per unit area: 1 / (total area) if spread evenly. An
  // importance shot is not worth it below a millionth of the view's importance.
  double area = 0;
  for (const auto& pa : state_.atlas.positionArea) area += pa.w;
  const float floor = float(settings_.importanceFloor / area);
  reduce_.set("importanceFloor", floor);
  select_.set("importanceFloor", floor);
  select_.set("importanceThreshold", 1e-6f);
  select_.set("uniformRatio", float(settings_.uniformRatio));
}

// The scene's BVH, for exact visibility: receivers near a shooter get its parts one by one
// (shaders/refine_near.glsl; nothing to refine where blocks have no parts), and with
// --visibility bvh every receiver traces its segment to each shooter (shaders/visibility.glsl).
// On a CPU device a plain solve's traced visibility is Embree's on the host (HostTrace.h), the
// same answers 20-30x sooner; importance and perspective shooters keep the GLSL walk.
void ProgressiveSolver::setUpBvh(gl::Defines& gatherDefines, std::span<const std::uint32_t> receivers,
                                 bool viewDriven) {
  if (!tracesBvh()) return;
  const Bvh bvh(state_.scene);
  bvh_ = BvhBuffers(bvh);
  if (refinesNear()) gatherDefines.push_back({"REFINE_NEAR", "1"});
  if (visibility_ != Visibility::Bvh) return;
  const bool host = settings_.hostTrace == HostTraceUse::Always ||
                    (settings_.hostTrace == HostTraceUse::OnCpuDevice && gl::softwareRenderer() && !viewDriven);
  // (A host trace of importance or perspective shooters would need their pass's other records.)
  if (!host) {
    gatherDefines.push_back({"BVH_VISIBILITY", "1"});
    return;
  }
  if (viewDriven) fail("host tracing serves plain progressive solves only");
  hostTrace_ =
      std::make_unique<HostTrace>(state_.scene, state_.atlas, bvh, receivers, unsigned(settings_.shootersPerPass),
                                  float(kSegmentTolerance * state_.farDistance));
  hostVisible_ = gl::Buffer(receivers.size() * hostTrace_->words() * sizeof(std::uint32_t));
  gatherDefines.push_back({"HOST_VISIBILITY", "1"});
  gatherDefines.push_back({"HOST_WORDS", std::to_string(hostTrace_->words())});
}

// The pass's visibility before its gather: its item buffers, or the host's answers.
void ProgressiveSolver::preparePassVisibility() {
  if (itemBuffer_) itemBuffer_->render(control_);
  if (!hostTrace_) return;
  ControlBlock c;  // the header and the pass's radiosity shooters, as select.comp chose them
  const std::size_t bytes = offsetof(ControlBlock, shooter) + settings_.shootersPerPass * sizeof(ShooterRecord);
  control_.read(0, bytes, &c);
  hostTrace_->trace(std::span<const ShooterRecord>(c.shooter, std::min(c.count, unsigned(settings_.shootersPerPass))),
                    hostBits_);
  hostVisible_.upload(0, hostBits_.size() * sizeof(std::uint32_t), hostBits_.data());
}

// The control block: stop rule, convergence history.
void ProgressiveSolver::setUpControl(const StopRule& stop, unsigned keep) {
  historyCapacity_ = stop.maxShots ? stop.maxShots + 1 : kUnlimitedHistory;
  ControlBlock c{};
  c.maxShots = stop.maxShots;
  c.targetConvergence = float(stop.targetConvergence);
  c.emittedPower = float(state_.emittedPower);
  c.historyCapacity = historyCapacity_;
  c.shootersPerPass = keep;
  control_ = gl::Buffer(sizeof(ControlBlock) + historyCapacity_ * sizeof(float));
  control_.upload(0, sizeof c, &c);
  statusCopies_ = gl::Readback(offsetof(ControlBlock, shooter), 2);  // the status header, not the shooters
}

ProgressiveSolver::~ProgressiveSolver() = default;

void ProgressiveSolver::selectPass(bool importanceOnly) {
  state_.bindScene();
  state_.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_ONLY);
  state_.deltaB.bindImage(slot::IMAGE_DELTA_B, GL_READ_ONLY);
  control_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_CONTROL);
  nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODES);
  nodeStats_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODE_STATS);
  if (perspective_) perspective_->bind();
  for (const StatsGroup& g : stats_) {  // a workgroup a block: past 65,535 blocks the grid tiles
    g.blocks.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_BLOCK_LIST);
    g.program.use();
    gl::dispatchLinear(g.count);
  }
  gl::barrier(gl::Barrier::Storage);
  if (!importanceOnly) rankPass(settings_.importanceDriven() ? Rank::PowerByImportance : Rank::Power, false);
  if (settings_.importanceDriven()) rankPass(Rank::Importance, true);
}

// Importance shooters only, no radiosity shot (the pass's radiosity count is 0).
void ProgressiveSolver::importancePass() {
  const std::uint32_t none = 0;
  control_.uploadAfterShaderWrites(offsetof(ControlBlock, count), sizeof none, &none);
  selectPass(true);
  preparePassVisibility();
  gatherPass(Receivers::InView);  // no radiosity shooter: only importance moves
  readStatus();
}

void ProgressiveSolver::look(const Camera& camera, double aspect) {
  if (!view_) throw std::logic_error("look() needs an importance-driven solver");
  // A fresh solve shoots the view's importance once before any light, so that its first
  // radiosity ranking already knows which lights the view needs (seed 004 §4.2.5 shoots
  // importance, then ranks radiosity by it); later passes propagate both together.
  if (view_->look(camera, aspect) && status_.shots == 0 && importanceShots_ == 0) importancePass();
  if (perspective_) {
    perspective_->look(camera, aspect, status_.shots);
    // The new view's deliveries may bring light: a finished solve has work again.
    if (!budgetSpent()) status_.done = false;
  }
}

// Seed 004 §5.5.3: one item buffer per block with entries for the surfaces entering the view,
// K a pass (fewer in the last), each entering surface receiving its own entry (Receivers::Entering).
// One pass; returns its item buffers.
unsigned ProgressiveSolver::deliverStored() {
  const unsigned n = unsigned(std::min<std::size_t>(settings_.shootersPerPass, perspective_->deliveriesLeft()));
  perspective_->describeDeliveries(n, control_);
  preparePassVisibility();
  gatherPass(Receivers::Entering);
  deliveryShots_ += n;
  if (perspective_->deliveriesLeft() == 0) {
    perspective_->finishDeliveries();
    // What was delivered is unshot again: a stopped solve goes on (unless its shots are spent).
    if (!budgetSpent()) {
      const std::uint32_t notDone = 0;
      control_.uploadAfterShaderWrites(offsetof(ControlBlock, done), sizeof notDone, &notDone);
      status_.done = false;
    }
  }
  return n;
}

// One ranking of the blocks and the selection from it.
void ProgressiveSolver::rankPass(Rank rank, bool importanceShooters) {
  const unsigned rankBy = unsigned(rank);
  // Many blocks: rank them 1024 at a time in parallel first; the last ranking runs in select.comp.
  unsigned n = unsigned(blockCount_);
  bool fromBlocks = true;
  reduce_.use();
  reduce_.set("rankBy", rankBy);
  for (gl::Buffer& level : levels_) {
    level.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_REDUCE_OUT);
    reduce_.set("count", n);
    reduce_.set("fromBlocks", int(fromBlocks));
    gl::dispatchLinear(gl::groupsFor(n, kGroupEntries));
    gl::barrier(gl::Barrier::Storage);
    level.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_REDUCE_IN);
    n = gl::groupsFor(n, kGroupEntries) * unsigned(settings_.shootersPerPass);
    fromBlocks = false;
  }
  select_.use();  // its count and input kind are fixed per scene: set in the constructor
  select_.set("rankBy", rankBy);
  select_.set("importanceShooters", int(importanceShooters));
  gl::Program::dispatch(1);
  gl::barrier(kAllBarriers);
}

void ProgressiveSolver::gatherPass(Receivers receivers) {
  if (perspective_) {
    perspective_->bind();
    gather_.set("viewMode", unsigned(receivers));
  }
  state_.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_WRITE);
  state_.deltaB.bindImage(slot::IMAGE_DELTA_B, GL_READ_WRITE);
  if (itemBuffer_)
    itemBuffer_->bindForLookup(state_, control_, shapes_);
  else
    bindShooterLookup(state_, control_, shapes_);
  if (refinesNear()) {
    nodes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODES);
    nodeStats_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_NODE_STATS);
  }
  if (tracesBvh()) bvh_.bind();
  receivers_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_RECEIVERS);
  if (hostTrace_) hostVisible_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_HOST_VISIBLE);
  gather_.use();
  auto dispatch = [&] {
    gl::dispatchLinear(gl::groupsFor(receiverCount_, kGatherGroup));
    gl::barrier(kAllBarriers);
  };
  if (refinesNear()) {  // transfer_split.glsl: the near pairs one shooter slot a dispatch, then the far pairs
    gather_.set("splitPhase", 0u);
    for (unsigned s = 0; s < unsigned(settings_.shootersPerPass); ++s) {
      gather_.set("nearSlot", s);
      dispatch();
    }
    gather_.set("splitPhase", 1u);
  }
  dispatch();
}

SolveStatus ProgressiveSolver::advance(unsigned shots) {
  const unsigned K = unsigned(settings_.shootersPerPass);
  const unsigned passes = (shots + K - 1) / K;
  if (!perspective_) {
    runPasses(passes);
    return readStatus();
  }
  advancePerspective(passes * K);
  return status_;
}

// Perspective-driven: while deliveries are due, delivery passes and shooting passes take turns
// (a moving camera brings new surfaces every frame: were shooting to wait for their entries, a
// walk would shoot nothing). The area of interest grows at fixed shot counts, so passes stop
// there (every pass but a solve's last shoots K). Whole passes in a fixed order: the result
// never depends on the batch sizes, which a resumed solve does not repeat.
void ProgressiveSolver::advancePerspective(unsigned budget) {
  const unsigned K = unsigned(settings_.shootersPerPass);
  while (budget > 0 && !(status_.done && budgetSpent())) {
    perspective_->update(status_.shots);  // a view that waited
    if (perspective_->delivering() && (perspective_->deliveryTurn() || status_.done)) {
      budget -= std::min(budget, deliverStored());
      continue;
    }
    if (status_.done) {
      if (!openWholeView()) return;
      continue;
    }
    budget -= std::min(budget, shootToNextStep(perspective_->delivering() ? K : budget));
    perspective_->shot();
  }
}

// Out of unshot light (or at the target) with entries still held back: the area of interest
// becomes the whole scene, so the solve ends where progressive refinement does. False when
// there is nothing left to open (or the shots are spent).
bool ProgressiveSolver::openWholeView() {
  if (budgetSpent() || perspective_->wholeScene()) return false;
  perspective_->showAll();
  return true;
}

// Whole passes up to the area of interest's next step (or the budget), then the step.
unsigned ProgressiveSolver::shootToNextStep(unsigned budget) {
  const unsigned K = unsigned(settings_.shootersPerPass);
  const unsigned toStep = perspective_->shotsToNextStep(status_.shots);
  const unsigned most = (budget + K - 1) / K;
  const unsigned run = toStep == PerspectiveView::kNoStep ? most : std::clamp((toStep + K - 1) / K, 1u, most);
  runPasses(run);
  readStatus();
  perspective_->grow(status_.shots);
  return run * K;
}

void ProgressiveSolver::runPasses(unsigned passes) {
  for (unsigned k = 0; k < passes && !status_.done; ++k, ++enqueued_) {
    const bool timed = timer_.due(enqueued_);  // totals are scaled from the timed passes
    if (timed) timer_.mark(kSelect);
    selectPass();
    if (timed) timer_.mark(kItemBuffer);
    preparePassVisibility();
    if (timed) timer_.mark(kGather);
    gatherPass(Receivers::InView);  // everyone receives when not perspective-driven
    if (timed) timer_.stop(), ++timed_;
  }
}

// State bytes: the control block's header, the convergence history, then (importance-driven)
// the direct importance R per atlas texel, then (perspective-driven) the view's state
// (PerspectiveView::save()), the delivery shots so far and the size of those two.
std::vector<std::uint8_t> ProgressiveSolver::saveState() const {
  constexpr std::size_t header = offsetof(ControlBlock, shooter);
  const std::size_t history = std::min(status_.shots + 1, historyCapacity_) * sizeof(float);
  std::vector<float> direct = view_ ? view_->readDirect() : std::vector<float>{};
  std::vector<std::uint8_t> bytes(header + history + direct.size() * sizeof(float));
  control_.read(0, header, bytes.data());
  control_.read(sizeof(ControlBlock), history, bytes.data() + header);
  if (!direct.empty())  // memcpy from an empty vector's null data() is UB (UBSan, ci/sanitize)
    std::memcpy(bytes.data() + header + history, direct.data(), direct.size() * sizeof(float));
  if (perspective_) {
    std::vector<std::uint8_t> view = perspective_->save();
    const auto* delivered = reinterpret_cast<const std::uint8_t*>(&deliveryShots_);
    view.insert(view.end(), delivered, delivered + sizeof deliveryShots_);
    const std::uint64_t size = view.size();
    bytes.insert(bytes.end(), view.begin(), view.end());
    bytes.insert(bytes.end(), reinterpret_cast<const std::uint8_t*>(&size),
                 reinterpret_cast<const std::uint8_t*>(&size + 1));
  }
  return bytes;
}

SolveStatus ProgressiveSolver::restoreState(std::span<const std::uint8_t> bytes) {
  while (statusCopies_.pending()) statusCopies_.wait();  // status read before the restore
  constexpr std::size_t header = offsetof(ControlBlock, shooter);
  if (perspective_) {  // its state sits at the end, followed by its size
    std::uint64_t size = 0;
    if (bytes.size() < sizeof size) throw InputError("checkpoint: progressive solver state is corrupt");
    std::memcpy(&size, bytes.data() + bytes.size() - sizeof size, sizeof size);
    if (size < sizeof deliveryShots_ || size > bytes.size() - sizeof size)
      throw InputError("checkpoint: progressive solver state is corrupt");
    const std::size_t at = bytes.size() - sizeof size - std::size_t(size),
                      view = std::size_t(size) - sizeof deliveryShots_;
    perspective_->restore(bytes.subspan(at, view));
    std::memcpy(&deliveryShots_, bytes.data() + at + view, sizeof deliveryShots_);
    bytes = bytes.first(at);
  }
  const std::size_t direct = view_ ? state_.atlas.positionArea.size() * sizeof(float) : 0;
  ControlBlock c{};
  if (bytes.size() < header + direct || (bytes.size() - header - direct) % sizeof(float) != 0)
    throw InputError("checkpoint: progressive solver state is corrupt");
  std::memcpy(&c, bytes.data(), header);
  // This run's stop rule; the shots and history go on from the checkpoint's.
  c.maxShots = settings_.stop.maxShots;
  c.targetConvergence = float(settings_.stop.targetConvergence);
  c.historyCapacity = historyCapacity_;
  c.done = 0;
  c.count = c.importanceCount = 0;
  control_.uploadAfterShaderWrites(0, header, &c);
  const std::size_t history = std::min<std::size_t>((bytes.size() - header - direct) / sizeof(float), historyCapacity_);
  control_.uploadAfterShaderWrites(sizeof(ControlBlock), history * sizeof(float), bytes.data() + header);
  if (view_) {
    std::vector<float> r(state_.atlas.positionArea.size());
    std::memcpy(r.data(), bytes.data() + bytes.size() - direct, direct);
    view_->restoreDirect(r);
  }
  status_ = {c.shots, c.convergence, false};
  importanceShots_ = c.importanceShots;
  return status_;
}

// Chunks of at most kAheadPasses passes, each followed by a copy of the status, reading the copy
// of the chunk before: the GPU always has a chunk queued while the CPU waits (on the H200 a
// Cornell pass takes 0.25 ms, about what a synchronous readback and the next submission left it
// idle), and once the stop rule fires at most one chunk of empty passes follows.
SolveStatus ProgressiveSolver::advanceAhead(unsigned shots) {
  if (perspective_) return advance(shots);
  const unsigned K = unsigned(settings_.shootersPerPass);
  for (unsigned passes = (shots + K - 1) / K; passes > 0 && !status_.done;) {
    const unsigned chunk = std::min(passes, kAheadPasses);
    runPasses(chunk);
    passes -= chunk;
    statusCopies_.copy(control_);
    if (statusCopies_.pending() > 1) collectStatus(false);  // the chunk just enqueued stays in flight
  }
  return status_;
}

SolveStatus ProgressiveSolver::settle(SolveStatus) {
  while (statusCopies_.pending()) collectStatus(true);
  return status_;
}

SolveStatus ProgressiveSolver::readStatus() {
  statusCopies_.copy(control_);
  return settle(status_);
}

SolveStatus ProgressiveSolver::collectStatus(bool waitForStamps) {
  const auto t0 = std::chrono::steady_clock::now();
  ControlBlock c;
  std::memcpy(&c, statusCopies_.wait(), statusCopies_.bytes());
  timings_.readback += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  timer_.collect(sampled_, waitForStamps);
  scaleSampledTimings(timings_, sampled_, enqueued_, timed_);
  gl::checkErrors("progressive shot");
  status_ = {c.shots, c.convergence, c.done != 0};
  importanceShots_ = c.importanceShots;
  if (status_.done && tracesBvh()) bvh_.requireWholeWalks("solve");  // a finished solve's exact visibility
  return status_;
}

std::vector<float> ProgressiveSolver::convergenceHistory() const {
  std::vector<float> h(std::min(status_.shots + 1, historyCapacity_));
  control_.read(sizeof(ControlBlock), h.size() * sizeof(float), h.data());
  return h;
}

}  // namespace hemirad
