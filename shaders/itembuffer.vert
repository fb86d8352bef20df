// Item buffer from the current shooter: the item mesh projected onto the hemisphere (seed 003)
// or one hemicube face, with depth = distance / far, so occlusion is ordered along each ray.
#include "hemisphere.glsl"
#include "control.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in uint polygon;
flat out uint vPolygon;
uniform float farDistance;
uniform int face;  // item-buffer layer: 0 for the hemisphere, 0-4 for the hemicube

void main() {
  vec3 local = shooterLocal(position, control.shooterPositionArea.xyz, control.shooterNormal.xyz);
  gl_Position = itemClipPosition(local, farDistance, face);
  // Only what lies above the shooter's plane is seen. The margin (float rounding of `local`)
  // also drops the shooter's coplanar neighbours, whose vertices would all land on the rim and
  // span the whole disc.
  gl_ClipDistance[0] = local.z - 1e-5 * farDistance;
  vPolygon = polygon;
  if (control.done != 0u) gl_Position = vec4(0.0, 0.0, 0.0, -1.0);  // once stopped, draw nothing
}
