// The solver's state on the GPU: the chosen shooter, the stop rule and the indirect
// arguments the selection pass writes, so a shot needs no CPU round trip.
// Mirrored by struct ControlBlock in src/ProgressiveSolver.cpp (std430, 144-byte header).

layout(std430, binding = 3) buffer Control {
  uvec4 gatherDispatch;  // x, y, z groups: zero once done
  uvec4 itemDraw;        // DrawArraysIndirectCommand: count, instanceCount (0 once done), first, base
  vec4 shooterPositionArea;
  vec4 shooterNormal;
  vec4 shooterDeltaB;    // rgb area-weighted unshot radiosity of the block, a: its power
  ivec4 shooterRect;     // atlas x, y, w, h of the shooting block
  uint shooterPolygon;
  uint shots;
  uint maxShots;         // 0: unlimited
  uint done;
  float targetConvergence;  // 0: none
  float emittedPower;
  float convergence;        // after `shots` shots
  float unshotPower;
  uint historyCapacity;
  uint gatherGroupsX;
  uint gatherGroupsY;
  uint pad0;
  float history[];          // convergence after k shots, k = 0..shots
} control;
