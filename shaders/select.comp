// The last level of the shooter reduction (one workgroup, over the blocks themselves when
// they are few), then the stop rule and the shooters of the next pass: the `keep` blocks that
// rank first (seed 003's batching), fewer when the shot budget or the power ends. With
// importanceShooters (importance-driven solves, after the radiosity selection of the same
// pass) it picks the pass's importance shooters instead, into slots keep, keep + 1, ...
// A chosen block shoots the part of itself that holds its light (src/solver/ShooterTree.h).
#include "hemisphere.glsl"
#include "scene.glsl"
#include "shooter_tree.glsl"
#include "reduce_entry.glsl"
#include "control.glsl"
#include "shooter_block.glsl"
#ifdef PERSPECTIVE
#include "perspective.glsl"
#endif

layout(local_size_x = 256) in;
uniform bool importanceShooters;
uniform float importanceThreshold;  // below this |dI| A a block is not worth an importance shot
// A node is cut when its elements' unshot radiosity (luminance) spans more than this ratio.
uniform float uniformRatio;
shared uint passShooters;

// Where block b's unshot light sits: down its tree while the node's radiosity is not uniform,
// into the child with the most unshot power (ties: the first). Perspective-driven solves keep
// whole blocks, whose shots their per-block tables record.
uint partOfBlock(uint b) {
  uint node = b;
#ifndef PERSPECTIVE
  while (nodes[node].firstChild != NO_CHILD && stats[node].range.x < uniformRatio * stats[node].range.y) {
    uint first = nodes[node].firstChild, best = first;
    for (uint c = first + 1u; c < first + 4u; ++c)
      if (luminance(stats[c].unshot.rgb) > luminance(stats[best].unshot.rgb)) best = c;
    node = best;
  }
#endif
  return node;
}

void main() {
  rankGroup(0u, count);
  uint l = gl_LocalInvocationID.x;
  if (l == 0u && importanceShooters) {
    uint n = 0u;
    if (control.done == 0u)
      while (n < keep && rankPower[n] > importanceThreshold) ++n;
    control.importanceCount = n;
    control.importanceShots += n;
    passShooters = n;
  } else if (l == 0u) {
    // Before the first shot the unshot power is the emitted power: taking this reduction's own
    // sum (not the CPU's double one) makes the history start at exactly 0, never -1e-7.
    if (control.shots == 0u) control.emittedPower = groupSum[0];
    float convergence = 1.0 - groupSum[0] / control.emittedPower;
    control.convergence = convergence;
    control.unshotPower = groupSum[0];
    bool stop = control.done != 0u || rankPower[0] <= 0.0 ||
                (control.maxShots != 0u && control.shots >= control.maxShots) ||
                (control.targetConvergence > 0.0 && convergence >= control.targetConvergence);
    uint n = 0u;
    if (!stop) {
      uint budget = control.maxShots != 0u ? min(keep, control.maxShots - control.shots) : keep;
      while (n < budget && rankPower[n] > 0.0) ++n;
    }
    // The shots of one pass are simultaneous: they share the convergence at its start.
    for (uint k = control.shots; k < control.shots + max(n, 1u) && k < control.historyCapacity; ++k)
      control.history[k] = convergence;
    control.done = stop ? 1u : 0u;
    control.count = n;
    control.importanceCount = 0u;
    control.shots += n;
    passShooters = n;
  }
  sync();
  if (l >= passShooters) return;
  uint block = rankIndex[l], node = importanceShooters ? block : partOfBlock(block);
  uint slot = importanceShooters ? keep + l : l;
  describeNode(slot, node, block);
  describeUnshot(slot, node, importanceShooters);
  control.shooter[slot].power = rankPower[l];
  control.nearDeficit[slot] = 0, control.nearShare[slot] = 0;
#ifdef PERSPECTIVE
  if (!importanceShooters) shotSoFar[rankIndex[l]] += control.shooter[slot].shot;  // one writer per block
#endif
}
