// Test probe (tests/HemisphereTest.cpp): formfactor.glsl's pointToPolygon on given cases, to
// compare with its double twin cpu::pointToPolygon. Case i: 16 vec4s: x, n (w: vertex count),
// front normal, then up to 12 vertices.
#include "hemisphere.glsl"
#include "formfactor.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = 0) readonly buffer In { vec4 cases[]; };
layout(std430, binding = 1) writeonly buffer Out { float result[]; };

void main() {
  uint base = gl_GlobalInvocationID.x * 16u;
  vec3 v[MAX_SHAPE_VERTICES];
  for (int k = 0; k < MAX_SHAPE_VERTICES; ++k) v[k] = cases[base + 3u + uint(k)].xyz;
  int count = int(cases[base + 1u].w);
  result[gl_GlobalInvocationID.x] = pointToPolygon(cases[base].xyz, cases[base + 1u].xyz, v, count, cases[base + 2u].xyz);
}
