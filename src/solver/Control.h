// The control block shared by the GPU passes (shaders/control.glsl, std430): the shooters of
// the current pass, the stop rule and the convergence history that follows it.
#pragma once
#include <cstdint>

#include "src/solver/ShaderContract.h"  // kMaxPassShooters, kShooterSlots

namespace hemirad {

struct ShooterRecord {
  float positionArea[4];
  float normal[4];
  float shot[4];
  std::int32_t rect[4];
  std::uint32_t polygon;
  float power;
  std::uint32_t block, shape;
};
static_assert(sizeof(ShooterRecord) == 80);

struct ControlBlock {
  std::uint32_t shots, maxShots, done, count;
  float targetConvergence, emittedPower, convergence, unshotPower;
  std::uint32_t historyCapacity, shootersPerPass, importanceCount, importanceShots;
  ShooterRecord shooter[kShooterSlots];
  std::int32_t nearDeficit[kShooterSlots], nearShare[kShooterSlots];  // TRANSFER_SPLIT's sums (gather.comp)
};
static_assert(sizeof(ControlBlock) == 48 + 88 * kShooterSlots);

}  // namespace hemirad
