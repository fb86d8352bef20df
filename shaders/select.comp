// The last level of the shooter reduction (one workgroup, over the blocks themselves when
// they are few), then the stop rule and the shooters of the next pass: the `keep` blocks that
// rank first (seed 003's batching), fewer when the shot budget or the power ends. With
// importanceShooters (importance-driven solves, after the radiosity selection of the same
// pass) it picks the pass's importance shooters instead, into slots keep, keep + 1, ...
#include "hemisphere.glsl"
#include "scene.glsl"
#include "reduce_entry.glsl"
#include "control.glsl"
#include "shooter_block.glsl"
#ifdef PERSPECTIVE
#include "perspective.glsl"
#endif

layout(local_size_x = 256) in;
uniform bool importanceShooters;
uniform float importanceThreshold;  // below this |dI| A a block is not worth an importance shot
shared uint passShooters;

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
  // The shooter shoots its area-weighted unshot radiosity (or importance) over its block's exact
  // shape, and sees from the block's unshot-power-weighted centre: a coarse block half under a
  // box would otherwise look out from inside the box and lose the lit half's light.
  ivec4 r = blockRect[rankIndex[l]];
  uint slot = importanceShooters ? keep + l : l;
  describeShooter(slot, r, rankIndex[l]);
  vec4 unshot = vec4(0.0);
  vec3 weightedCentre = vec3(0.0);
  float weight = 0.0;
  for (int y = r.y; y < r.y + r.w; ++y)
    for (int x = r.x; x < r.x + r.z; ++x) {
      vec4 pa = texelFetch(atlasPositionArea, ivec2(x, y), 0), d = imageLoad(deltaB, ivec2(x, y));
      unshot += d * pa.w;
      float w = (importanceShooters ? abs(d.a) : luminance(d.rgb)) * pa.w;
      weightedCentre += w * pa.xyz;
      weight += w;
    }
  if (weight > 0.0) control.shooter[slot].positionArea.xyz = weightedCentre / weight;
  float area = control.shooter[slot].positionArea.w;
  control.shooter[slot].shot = importanceShooters ? vec4(0.0, 0.0, 0.0, unshot.a / area) : vec4(unshot.rgb / area, 0.0);
  control.shooter[slot].power = rankPower[l];
#ifdef PERSPECTIVE
  if (!importanceShooters) shotSoFar[rankIndex[l]] += control.shooter[slot].shot;  // one writer per block
#endif
}
