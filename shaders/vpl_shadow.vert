// Hemispherical shadow maps of a batch of VPLs in one layered, instanced draw: instance i draws
// the item mesh from VPL vplFirst + i into layer i with the item buffer's projection (a VPL is a
// point on a diffuse surface, so its hemisphere is exactly an item buffer, seed 003).
#extension GL_ARB_shader_viewport_layer_array : require
#include "hemisphere.glsl"
#include "vpl.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in uint polygon;
flat out uint vPolygon;
flat out uint vVpl;
uniform uint vplFirst;
uniform float farDistance;

void main() {
  uint v = vplFirst + uint(gl_InstanceID);
  gl_Layer = gl_InstanceID;
  vPolygon = polygon;
  vVpl = v;
  if (vpl[v].flux.rgb == vec3(0.0)) {  // an empty slot: draws nothing
    gl_Position = vec4(0.0, 0.0, 0.0, -1.0);
    gl_ClipDistance[0] = -1.0;
    return;
  }
  vec3 local = shooterLocal(position, vpl[v].position.xyz, vpl[v].normal.xyz);
  gl_Position = itemClipPosition(local, farDistance, 0);
  gl_ClipDistance[0] = local.z - 1e-5 * farDistance;  // as the item buffer: above the VPL's plane only
}
