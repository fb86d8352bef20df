#include "src/ProgressiveSolver.h"

#include <algorithm>
#include <chrono>
#include <cstddef>

#include "gl/Debug.h"
#include "gl/Shader.h"
#include "gl/Timer.h"
#include "src/ItemMesh.h"

namespace hemirad {

namespace {

constexpr std::uint32_t kNoPolygonClear = kNoPolygon;
constexpr unsigned kGatherGroup = 16;   // gather.comp local size (x and y)
constexpr unsigned kPowerGroup = 64;    // block_power.comp
constexpr unsigned kReduceFold = 1024;  // entries folded per reduce.comp workgroup
constexpr unsigned kUnlimitedHistory = 1u << 20;

// shaders/control.glsl, std430.
struct ControlBlock {
  std::uint32_t gatherDispatch[4];
  std::uint32_t itemDraw[4];
  float shooterPositionArea[4];
  float shooterNormal[4];
  float shooterDeltaB[4];
  std::int32_t shooterRect[4];
  std::uint32_t shooterPolygon, shots, maxShots, done;
  float targetConvergence, emittedPower, convergence, unshotPower;
  std::uint32_t historyCapacity, gatherGroupsX, gatherGroupsY, pad0;
};
static_assert(sizeof(ControlBlock) == 144);
constexpr std::size_t kDrawOffset = offsetof(ControlBlock, itemDraw);

enum Slot { kSelect, kItemBuffer, kGather, kSlots };

constexpr GLbitfield kAllBarriers = GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                    GL_COMMAND_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT;

}  // namespace

struct ProgressiveSolver::Timers {
  gl::GpuTimer gpu;
};

ProgressiveSolver::ProgressiveSolver(SolverState& state, const ProgressiveSettings& settings)
    : state_(state), settings_(settings), timers_(std::make_unique<Timers>()) {
  blockPower_ = gl::computeProgram("block_power.comp");
  reduce_ = gl::computeProgram("reduce.comp");
  select_ = gl::computeProgram("select.comp");
  gather_ = gl::computeProgram("gather.comp");
  itemBuffer_ = gl::renderProgram("itembuffer.vert", "itembuffer.frag");

  // Shooter blocks and the reduction levels above them.
  std::vector<ShooterBlock> blocks = state.atlas.shooterBlocks(settings.shootLevel);
  blockCount_ = blocks.size();
  blocks_ = gl::Buffer(std::span<const ShooterBlock>(blocks));
  for (std::size_t n = blockCount_;; n = gl::groupsFor(unsigned(n), kReduceFold)) {
    levels_.emplace_back(std::max<std::size_t>(n, 1) * 16);
    if (n <= 1) break;
  }

  // Item mesh in a static buffer: position + polygon id.
  std::vector<ItemVertex> mesh = buildItemMesh(state.scene, settings.itemSubdivision);
  itemVertexCount_ = mesh.size();
  itemVertices_ = gl::Buffer(std::span<const ItemVertex>(mesh));
  GLuint vao = itemVao_.id();
  glVertexArrayVertexBuffer(vao, 0, itemVertices_.id(), 0, sizeof(ItemVertex));
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(ItemVertex, x));
  glVertexArrayAttribBinding(vao, 0, 0);
  glEnableVertexArrayAttrib(vao, 1);
  glVertexArrayAttribIFormat(vao, 1, 1, GL_UNSIGNED_INT, offsetof(ItemVertex, polygon));
  glVertexArrayAttribBinding(vao, 1, 0);

  int res = settings.itemResolution;
  itemId_ = gl::Texture(GL_R32UI, res, res);
  itemDepth_ = gl::Texture(GL_DEPTH_COMPONENT32F, res, res);
  itemFbo_.attach(GL_COLOR_ATTACHMENT0, itemId_);
  itemFbo_.attach(GL_DEPTH_ATTACHMENT, itemDepth_);
  itemFbo_.checkComplete("item buffer");

  // The control block: stop rule, indirect arguments, convergence history.
  const StopRule& stop = settings.stop;
  historyCapacity_ = stop.maxShots ? stop.maxShots + 1 : kUnlimitedHistory;
  ControlBlock c{};
  c.itemDraw[0] = std::uint32_t(itemVertexCount_);
  c.maxShots = stop.maxShots;
  c.targetConvergence = float(stop.targetConvergence);
  c.emittedPower = float(state.emittedPower);
  c.historyCapacity = historyCapacity_;
  c.gatherGroupsX = gl::groupsFor(unsigned(state.atlas.width), kGatherGroup);
  c.gatherGroupsY = gl::groupsFor(unsigned(state.atlas.height), kGatherGroup);
  control_ = gl::Buffer(sizeof(ControlBlock) + historyCapacity_ * sizeof(float));
  control_.upload(0, sizeof c, &c);

  float far = float(state.farDistance);
  itemBuffer_.set("farDistance", far);
  gather_.set("farDistance", far);
  glProgramUniform2i(gather_.id(), gather_.location("atlasSize"), state.atlas.width, state.atlas.height);
  blockPower_.set("blockCount", unsigned(blockCount_));
  gl::checkErrors("progressive solver setup");
}

ProgressiveSolver::~ProgressiveSolver() = default;

void ProgressiveSolver::selectPass() {
  state_.bindScene();
  state_.deltaB.bindImage(1, GL_READ_ONLY);
  blocks_.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  levels_[0].bindBase(GL_SHADER_STORAGE_BUFFER, 2);
  blockPower_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(blockCount_), kPowerGroup));
  reduce_.use();
  for (std::size_t l = 0, n = blockCount_; l + 1 < levels_.size(); ++l, n = gl::groupsFor(unsigned(n), kReduceFold)) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    levels_[l].bindBase(GL_SHADER_STORAGE_BUFFER, 2);
    levels_[l + 1].bindBase(GL_SHADER_STORAGE_BUFFER, 4);
    reduce_.set("count", unsigned(n));
    gl::Program::dispatch(gl::groupsFor(unsigned(n), kReduceFold));
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  levels_.back().bindBase(GL_SHADER_STORAGE_BUFFER, 4);
  control_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  select_.use();
  gl::Program::dispatch(1);
  glMemoryBarrier(kAllBarriers);
}

void ProgressiveSolver::itemBufferPass() {
  const GLuint clearId[4] = {kNoPolygonClear, 0, 0, 0};
  const float far = 1.0f;
  glClearNamedFramebufferuiv(itemFbo_.id(), GL_COLOR, 0, clearId);
  glClearNamedFramebufferfv(itemFbo_.id(), GL_DEPTH, 0, &far);
  itemFbo_.bind();
  glViewport(0, 0, settings_.itemResolution, settings_.itemResolution);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // every face occludes from both sides
  glEnable(GL_CLIP_DISTANCE0);
  control_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  control_.bind(GL_DRAW_INDIRECT_BUFFER);
  itemBuffer_.use();
  itemVao_.bind();
  glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(kDrawOffset));
  glDisable(GL_CLIP_DISTANCE0);
}

void ProgressiveSolver::gatherPass() {
  state_.bindScene();
  state_.radiosity.bindImage(0, GL_READ_WRITE);
  state_.deltaB.bindImage(1, GL_READ_WRITE);
  itemId_.bindUnit(2);
  itemDepth_.bindUnit(3);
  control_.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  gather_.use();
  gl::Program::dispatchIndirect(control_, 0);
  glMemoryBarrier(kAllBarriers);
}

SolveStatus ProgressiveSolver::advance(unsigned shots) {
  gl::GpuTimer& timer = timers_->gpu;
  for (unsigned k = 0; k < shots && !status_.done; ++k) {
    timer.begin(kSelect);
    selectPass();
    timer.end();
    timer.begin(kItemBuffer);
    itemBufferPass();
    timer.end();
    timer.begin(kGather);
    gatherPass();
    timer.end();
  }
  return readStatus();
}

SolveStatus ProgressiveSolver::readStatus() {
  auto t0 = std::chrono::steady_clock::now();
  ControlBlock c;
  control_.read(0, sizeof c, &c);
  timings_.readback += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  double totals[kSlots] = {};
  timers_->gpu.collect(totals);
  timings_.select += totals[kSelect];
  timings_.itemBuffer += totals[kItemBuffer];
  timings_.gather += totals[kGather];
  gl::checkErrors("progressive shot");
  status_ = {c.shots, c.convergence, c.done != 0};
  return status_;
}

std::vector<float> ProgressiveSolver::convergenceHistory() const {
  std::vector<float> h(std::min(status_.shots + 1, historyCapacity_));
  control_.read(sizeof(ControlBlock), h.size() * sizeof(float), h.data());
  return h;
}

}  // namespace hemirad
