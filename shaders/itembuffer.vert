// Item buffer from the current shooter: the item mesh projected onto the hemisphere
// (seed 003) with depth = distance / far, so occlusion is ordered along each ray.
#include "hemisphere.glsl"
#include "control.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in uint polygon;
flat out uint vPolygon;
uniform float farDistance;

void main() {
  vec3 local = shooterLocal(position, control.shooterPositionArea.xyz, control.shooterNormal.xyz);
  float dist = length(local);
  gl_Position = vec4(hemiProject(local), 2.0 * dist / farDistance - 1.0, 1.0);
  // Only what lies above the shooter's plane is seen. The margin (float rounding of `local`)
  // also drops the shooter's coplanar neighbours, whose vertices would all land on the rim and
  // span the whole disc.
  gl_ClipDistance[0] = local.z - 1e-5 * farDistance;
  vPolygon = polygon;
}
