// The solver's state on the GPU: the shooters of the current pass and the stop rule, written by
// the selection pass, so a shot needs no CPU round trip. Once `done` is set every later pass of
// the batch returns at once (draws and dispatches stay direct: on NVIDIA, indirect arguments
// written by the previous pass cost ~1 ms of latency a shot). Mirrored by src/Control.h (std430).

const uint MAX_PASS_SHOOTERS = 64u;

struct Shooter {
  vec4 positionArea;  // area-weighted centre of the block, its area
  vec4 normal;
  vec4 deltaB;        // rgb area-weighted unshot radiosity of the block, a: its power
  ivec4 rect;         // atlas x, y, w, h of the shooting block
  uint polygon;
  uint pad0, pad1, pad2;
};

layout(std430, binding = 3) buffer Control {
  uint shots;
  uint maxShots;            // 0: unlimited
  uint done;
  uint count;               // shooters in this pass (seed 003's batching), 0 once done
  float targetConvergence;  // 0: none
  float emittedPower;
  float convergence;        // after `shots` shots
  float unshotPower;
  uint historyCapacity;
  uint shootersPerPass;     // the most shooters a pass takes
  uint pad0, pad1;
  Shooter shooter[MAX_PASS_SHOOTERS];
  float history[];          // convergence after k shots, k = 0..shots (per pass: see select.comp)
} control;
