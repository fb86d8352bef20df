// Test probe (tests/HemisphereTest.cpp): projects directions given in the shooter's frame,
// placed 4 units away in world space, through hemisphere.glsl.
#include "hemisphere.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = SSBO_PROBE_IN) readonly buffer In { vec4 dirs[]; };
layout(std430, binding = SSBO_PROBE_OUT) writeonly buffer Out { vec4 result[]; };
uniform vec3 normal;
uniform vec3 origin;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec3 t, b;
  shooterBasis(normal, t, b);
  vec3 d = dirs[i].xyz;
  vec3 world = origin + 4.0 * (d.x * t + d.y * b + d.z * normal);
  vec2 p = hemiProject(shooterLocal(world, origin, normal));
  result[i] = vec4(p, discFormFactor(0.8, 0.6, 2.0, 0.5), 0.0);
}
