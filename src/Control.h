// The control block shared by the GPU passes (shaders/control.glsl, std430): the shooter, the
// stop rule, indirect arguments and the convergence history that follows it.
#pragma once
#include <cstddef>
#include <cstdint>

namespace hemirad {

struct ControlBlock {
  std::uint32_t gatherDispatch[4];  // DispatchIndirectCommand (x, y, z) + pad
  std::uint32_t itemDraw[4];        // DrawArraysIndirectCommand
  float shooterPositionArea[4];
  float shooterNormal[4];
  float shooterDeltaB[4];
  std::int32_t shooterRect[4];
  std::uint32_t shooterPolygon, shots, maxShots, done;
  float targetConvergence, emittedPower, convergence, unshotPower;
  std::uint32_t historyCapacity, gatherGroupsX, gatherGroupsY, pad0;
};
static_assert(sizeof(ControlBlock) == 144);
constexpr std::size_t kItemDrawOffset = offsetof(ControlBlock, itemDraw);

}  // namespace hemirad
