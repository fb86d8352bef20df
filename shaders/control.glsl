// The solver's state on the GPU: the shooters of the current pass and the stop rule, written by
// the selection pass, so a shot needs no CPU round trip. Once `done` is set every later pass of
// the batch returns at once (draws and dispatches stay direct: on NVIDIA, indirect arguments
// written by the previous pass cost ~1 ms of latency a shot). Mirrored by src/solver/Control.h (std430);
// SHOOTER_SLOTS (src/solver/ShaderContract.h): as many radiosity as importance shooters.

// Slot s holds a shooter of this pass.
#define activeShooter(s) ((s) < control.count || ((s) >= control.shootersPerPass && (s) < control.shootersPerPass + control.importanceCount))

struct Shooter {
  vec4 positionArea;  // area-weighted centre of the block, its area
  vec4 normal;
  vec4 shot;          // what it shoots, area-weighted over the block: unshot radiosity (rgb) or
                      // unshot importance (a), the other part 0
  ivec4 rect;         // atlas x, y, w, h of the shooting block
  uint polygon;
  float power;        // the ranking key it was chosen by
  uint block;         // its index among the shooter blocks
  uint shape;         // the shooter-tree node it shoots from (shooter_tree.glsl): its shape
};

layout(std430, binding = SSBO_CONTROL) buffer Control {
  uint shots;
  uint maxShots;            // 0: unlimited
  uint done;
  uint count;               // shooters in this pass (seed 003's batching), 0 once done
  float targetConvergence;  // 0: none
  float emittedPower;
  float convergence;        // after `shots` shots
  float unshotPower;
  uint historyCapacity;
  uint shootersPerPass;     // K: radiosity shooters are shooter[0, count), importance shooters
  uint importanceCount;     //    (importance-driven solves) shooter[K, K + importanceCount)
  uint importanceShots;     // importance shots so far
  Shooter shooter[SHOOTER_SLOTS];
  // TRANSFER_SPLIT (gather.comp), per radiosity shooter of the pass, in 2^-24 of its shot power
  // (integers: atomic sums in any order give the same bits): what its near receivers took less
  // than its uniform light gives them, and what that light gives them.
  int nearDeficit[SHOOTER_SLOTS];
  int nearShare[SHOOTER_SLOTS];
  float history[];          // convergence after k shots, k = 0..shots (per pass: see select.comp)
} control;
