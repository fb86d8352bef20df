// The last level of the shooter reduction (one workgroup, over the blocks themselves when
// they are few), then the stop rule and the next shooter.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "reduce_entry.glsl"
#include "control.glsl"

layout(local_size_x = 256) in;

void main() {
  reduceGroup(0u, count);
  if (gl_LocalInvocationID.x != 0u) return;
  Entry w = partial[0];
  float convergence = 1.0 - w.sum / control.emittedPower;
  control.convergence = convergence;
  control.unshotPower = w.sum;
  if (control.shots < control.historyCapacity) control.history[control.shots] = convergence;
  bool stop = control.done != 0u || w.best <= 0.0 ||
              (control.maxShots != 0u && control.shots >= control.maxShots) ||
              (control.targetConvergence > 0.0 && convergence >= control.targetConvergence);
  if (stop) {
    control.done = 1u;
    return;
  }
  // The block shoots from its area-weighted centre with its area-weighted unshot radiosity.
  ivec4 r = blockRect[w.index];
  vec3 power = vec3(0.0), centre = vec3(0.0);
  float area = 0.0;
  uint polygon = NO_POLYGON;
  for (int y = r.y; y < r.y + r.w; ++y)
    for (int x = r.x; x < r.x + r.z; ++x) {
      vec4 pa = texelFetch(atlasPositionArea, ivec2(x, y), 0);
      if (pa.w <= 0.0) continue;
      power += imageLoad(deltaB, ivec2(x, y)).rgb * pa.w;
      centre += pa.xyz * pa.w;
      area += pa.w;
      polygon = texelFetch(atlasPolygon, ivec2(x, y), 0).r;
    }
  control.shooterPositionArea = vec4(centre / area, area);
  control.shooterNormal = vec4(polygons[polygon].normal.xyz, 0.0);
  control.shooterDeltaB = vec4(power / area, w.best);
  control.shooterRect = r;
  control.shooterPolygon = polygon;
  control.shots += 1u;
}
