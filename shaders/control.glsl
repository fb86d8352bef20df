// The solver's state on the GPU: the chosen shooter and the stop rule, written by the selection
// pass, so a shot needs no CPU round trip. Once `done` is set every later pass of the batch
// returns at once (draws and dispatches stay direct: on NVIDIA, indirect arguments written by
// the previous pass cost ~1 ms of latency a shot). Mirrored by src/Control.h (std430).

layout(std430, binding = 3) buffer Control {
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
  uint pad0, pad1, pad2;
  float history[];          // convergence after k shots, k = 0..shots
} control;
