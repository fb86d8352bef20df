// The control block shared by the GPU passes (shaders/control.glsl, std430): the shooters of
// the current pass, the stop rule and the convergence history that follows it.
#pragma once
#include <cstdint>

namespace hemirad {

inline constexpr unsigned kMaxPassShooters = 64;  // MAX_PASS_SHOOTERS in control.glsl

struct ShooterRecord {
  float positionArea[4];
  float normal[4];
  float deltaB[4];
  std::int32_t rect[4];
  std::uint32_t polygon, pad[3];
};
static_assert(sizeof(ShooterRecord) == 80);

struct ControlBlock {
  std::uint32_t shots, maxShots, done, count;
  float targetConvergence, emittedPower, convergence, unshotPower;
  std::uint32_t historyCapacity, shootersPerPass, pad[2];
  ShooterRecord shooter[kMaxPassShooters];
};
static_assert(sizeof(ControlBlock) == 48 + 80 * kMaxPassShooters);

}  // namespace hemirad
