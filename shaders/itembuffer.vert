// Item buffers of the pass's shooters: layer i holds the item mesh drawn from shooter
// i / ITEM_FACES, projected onto the hemisphere (seed 003) or one hemicube face, with depth =
// distance / far, so occlusion is ordered along each ray. The chunks a layer may see are its
// indirect draws (cull_items.comp), `layer` their per-instance attribute.
#extension GL_ARB_shader_viewport_layer_array : require
#include "hemisphere.glsl"
#include "control.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in uint polygon;
layout(location = 2) in uint layer;
flat out uint vPolygon;
flat out int vLayer;
uniform float farDistance;

void main() {
  uint shooter = layer / uint(ITEM_FACES);
  int face = int(layer % uint(ITEM_FACES));
  gl_Layer = int(layer);
  vPolygon = polygon;
  vLayer = int(layer);
  if (!activeShooter(shooter)) {  // a short pass, or the stop rule fired: draw nothing
    gl_Position = vec4(0.0, 0.0, 0.0, -1.0);
    gl_ClipDistance[0] = -1.0;
    return;
  }
  vec3 local = shooterLocal(position, control.shooter[shooter].positionArea.xyz, control.shooter[shooter].normal.xyz);
  gl_Position = itemClipPosition(local, farDistance, face);
  // Only what lies above the shooter's plane is seen. The margin (float rounding of `local`)
  // also drops the shooter's coplanar neighbours, whose vertices would all land on the rim and
  // span the whole disc.
  gl_ClipDistance[0] = local.z - 1e-5 * farDistance;
}
