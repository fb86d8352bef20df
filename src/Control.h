// The control block shared by the GPU passes (shaders/control.glsl, std430): the shooter, the
// stop rule and the convergence history that follows it.
#pragma once
#include <cstdint>

namespace hemirad {

struct ControlBlock {
  float shooterPositionArea[4];
  float shooterNormal[4];
  float shooterDeltaB[4];
  std::int32_t shooterRect[4];
  std::uint32_t shooterPolygon, shots, maxShots, done;
  float targetConvergence, emittedPower, convergence, unshotPower;
  std::uint32_t historyCapacity, pad[3];
};
static_assert(sizeof(ControlBlock) == 112);

}  // namespace hemirad
