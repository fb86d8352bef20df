#include "src/solver/StochasticSolver.h"

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "gl/Debug.h"
#include "gl/State.h"
#include "src/base/Error.h"
#include "src/solver/Control.h"
#include "src/solver/ShaderContract.h"
#include "src/solver/ShootingPlan.h"
#include "src/solver/TexelParts.h"

namespace hemirad {

namespace {

constexpr unsigned kGroup2D = 16;                  // pyramid.comp and stochastic_update.comp local size (x and y)
constexpr unsigned kSampleGroup = 64;              // sample.comp local size
constexpr std::uint32_t kStateMagic = 0x53544331;  // "STC1"

enum Slot { kSelect, kItemBuffer, kUpdate };

constexpr gl::Barrier kAllBarriers = gl::Barrier::Storage | gl::Barrier::Image | gl::Barrier::TextureFetch;

struct SavedState {
  std::uint32_t magic, iterations, seed, shooters;
};

}  // namespace

Source parseSource(const std::string& name) {
  if (name == "iterate") return Source::Iterate;
  if (name == "mean") return Source::Mean;
  throw InputError("--transport must be iterate or mean, not '" + name + "'");
}

const char* sourceName(Source s) { return s == Source::Mean ? "mean" : "iterate"; }

StochasticSolver::StochasticSolver(SolverState& state, const StochasticSettings& settings)
    : state_(state), settings_(settings), timer_(gl::contextTimerMode(settings.timings)) {
  if (settings.shooters < 1 || unsigned(settings.shooters) > kMaxPassShooters)
    throw InputError(fmt::format("--shooters-per-pass must be 1 to {}, not {}", kMaxPassShooters, settings.shooters));
  if (settings.stop.targetConvergence > 0)
    throw InputError(
        "--method stochastic has no convergence measure: stop it with --shots (iterations), not --converge");
  itemResolution_ =
      planShooting(state.scene, state.atlas, 0, settings.itemResolution, settings.projection).itemResolution;
  while (side_ < unsigned(std::max(state.atlas.width, state.atlas.height))) side_ *= 2, ++levels_;
  std::size_t floats = 0;
  for (unsigned l = 0; l < levels_; ++l) floats += std::size_t(side_ >> l) * (side_ >> l);
  pyramidSums_ = gl::Buffer(floats * sizeof(float));
  const TexelParts parts = texelParts(state.atlas);
  charts_ = gl::Buffer(std::span<const glm::vec4>(parts.charts));
  texelParts_ = gl::Buffer(std::span<const std::uint32_t>(parts.index));
  // Slot k and each sampled texel's other pieces (texel_shape.glsl).
  shapes_ = gl::Buffer(std::size_t(kShooterSlots) * kMaxTexelPieces * kShapeStride * sizeof(float[4]));
  const unsigned K = unsigned(settings.shooters);
  itemBuffer_ = std::make_unique<ItemBuffer>(state.scene, settings.itemSubdivision, itemResolution_, state.farDistance,
                                             settings.projection, settings.shooters);
  pyramid_ = computeProgram("pyramid.comp");
  sample_ = computeProgram("sample.comp");
  update_ = computeProgram("stochastic_update.comp", itemBuffer_->defines());
  pyramid_.set("pyramidSide", side_);
  pyramid_.set("atlasSize", state.atlas.width, state.atlas.height);
  sample_.set("pyramidSide", side_);
  sample_.set("seed", unsigned(settings.seed));
  sample_.set("shooters", K);
  sample_.set("topLevel", levels_ - 1);
  sample_.set("atlasWidth", unsigned(state.atlas.width));
  update_.set("atlasSize", state.atlas.width, state.atlas.height);
  update_.set("farDistance", float(state.farDistance));
  ControlBlock c{};
  c.maxShots = settings.stop.maxShots;
  c.count = c.shootersPerPass = K;
  c.emittedPower = float(state.emittedPower);
  control_ = gl::Buffer(sizeof(ControlBlock), &c);
  gl::checkErrors("stochastic solver setup");
}

StochasticSolver::~StochasticSolver() = default;

// Level 0 from B, then each level from the one below: log2(side) + 1 dispatches.
void StochasticSolver::pyramidPass(const gl::Texture& source) {
  state_.bindScene();
  source.bindImage(slot::IMAGE_RADIOSITY, GL_READ_ONLY);
  pyramidSums_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PYRAMID);
  pyramid_.use();
  for (unsigned l = 0; l < levels_; ++l) {
    pyramid_.set("level", l);
    const unsigned groups = gl::groupsFor(side_ >> l, kGroup2D);
    gl::Program::dispatch(groups, groups);
    gl::barrier(gl::Barrier::Storage);
  }
}

void StochasticSolver::samplePass(const gl::Texture& source, std::uint32_t key) {
  state_.bindScene();
  source.bindImage(slot::IMAGE_RADIOSITY, GL_READ_ONLY);
  pyramidSums_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PYRAMID);
  charts_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_CHARTS);
  texelParts_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_TEXEL_PARTS);
  control_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_CONTROL);
  shapes_.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_SHOOTER_SHAPES);
  sample_.use();
  sample_.set("iteration", unsigned(key));
  gl::Program::dispatch(gl::groupsFor(unsigned(settings_.shooters), kSampleGroup));
  gl::barrier(kAllBarriers);
}

void StochasticSolver::updatePass(float weight, float emission) {
  state_.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_WRITE);
  state_.deltaB.bindImage(slot::IMAGE_DELTA_B, GL_WRITE_ONLY);
  itemBuffer_->bindForLookup(state_, control_, shapes_);
  update_.use();
  update_.set("weight", weight);
  update_.set("emission", emission);
  gl::Program::dispatch(gl::groupsFor(unsigned(state_.atlas.width), kGroup2D),
                        gl::groupsFor(unsigned(state_.atlas.height), kGroup2D));
  gl::barrier(kAllBarriers);
}

void StochasticSolver::iterate(const gl::Texture& source, std::uint32_t key, float weight, float emission) {
  const bool timed = timer_.due(enqueued_);  // totals are scaled from the timed iterations
  ++enqueued_;
  if (timed) timer_.mark(kSelect);
  pyramidPass(source);
  samplePass(source, key);
  if (timed) timer_.mark(kItemBuffer);
  itemBuffer_->render(control_);
  if (timed) timer_.mark(kUpdate);
  updatePass(weight, emission);
  if (timed) timer_.stop(), ++timed_;
}

SolveStatus StochasticSolver::advance(unsigned iterations) {
  const unsigned limit = settings_.stop.maxShots;
  for (unsigned k = 0; k < iterations && !(limit && status_.shots >= limit); ++k) {
    const std::uint32_t m = ++status_.shots;  // 1-based: B~_m = (1 - 1/m) B~_{m-1} + (1/m) L_m
    const unsigned span = settings_.window && m > settings_.window ? settings_.window : m;
    iterate(settings_.source == Source::Mean ? state_.radiosity : state_.deltaB, m, 1.0f / float(span), 1.0f);
  }
  // The only readback: the iteration count the GPU last saw, which also waits for the batch.
  const auto t0 = std::chrono::steady_clock::now();
  std::uint32_t gpuShots = 0;
  control_.read(0, sizeof gpuShots, &gpuShots);
  timings_.readback += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  timer_.collect(sampled_);
  scaleSampledTimings(timings_, sampled_, enqueued_, timed_);
  gl::checkErrors("stochastic iteration");
  if (gpuShots != status_.shots) throw std::logic_error("stochastic solver: GPU and CPU iteration counts differ");
  status_.convergence = std::numeric_limits<double>::quiet_NaN();
  status_.done = limit && status_.shots >= limit;
  return status_;
}

void StochasticSolver::applyOperator(std::uint32_t key) { iterate(state_.radiosity, key, 1.0f, 0.0f); }

std::vector<float> StochasticSolver::convergenceHistory() const {
  return std::vector<float>(status_.shots + 1, std::numeric_limits<float>::quiet_NaN());
}

std::vector<std::uint8_t> StochasticSolver::saveState() const {
  const SavedState s{kStateMagic, status_.shots, settings_.seed, unsigned(settings_.shooters)};
  std::vector<std::uint8_t> bytes(sizeof s);
  std::memcpy(bytes.data(), &s, sizeof s);
  return bytes;
}

SolveStatus StochasticSolver::restoreState(std::span<const std::uint8_t> bytes) {
  SavedState s{};
  if (bytes.size() != sizeof s) throw InputError("checkpoint: stochastic solver state is corrupt");
  std::memcpy(&s, bytes.data(), sizeof s);
  if (s.magic != kStateMagic) throw InputError("checkpoint: stochastic solver state is corrupt");
  if (s.seed != settings_.seed || s.shooters != unsigned(settings_.shooters))
    throw InputError(fmt::format("checkpoint was made with --seed {} --shooters-per-pass {}; resume with the same",
                                 s.seed, s.shooters));
  status_.shots = s.iterations;
  status_.convergence = std::numeric_limits<double>::quiet_NaN();
  status_.done = false;
  control_.uploadAfterShaderWrites(0, sizeof s.iterations, &s.iterations);
  return status_;
}

}  // namespace hemirad
