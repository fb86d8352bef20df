// Test probe (tests/HemisphereTest.cpp): the item buffer's projection as compiled for one
// projection (the defines of src/solver/ItemBuffer.cpp), on shooter-frame points placed 4 units
// away in world space, and its inverse on given item-buffer points.
#include "hemisphere.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = SSBO_PROBE_IN) readonly buffer In { vec4 dirs[]; };  // xyz: direction, w unused
layout(std430, binding = SSBO_PROBE_POINTS) readonly buffer Points { vec4 points[]; };  // xy: ndc, z: layer
layout(std430, binding = SSBO_PROBE_OUT) writeonly buffer Out { vec4 result[]; };   // three per input
uniform vec3 normal;
uniform vec3 origin;
uniform float farDistance;
uniform int size;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec3 t, b;
  shooterBasis(normal, t, b);
  vec3 d = dirs[i].xyz;
  vec3 local = shooterLocal(origin + 4.0 * (d.x * t + d.y * b + d.z * normal), origin, normal);
  ivec3 texel = itemTexel(local, ivec2(size));
  vec4 clip = itemClipPosition(local, farDistance, texel.z);
  result[3u * i] = vec4(clip.xyz / clip.w, float(texel.z));
  result[3u * i + 1u] = vec4(vec2(texel.xy), 0.0, 0.0);
  result[3u * i + 2u] = vec4(normalize(itemDirection(points[i].xy, int(points[i].z))), 0.0);
}
