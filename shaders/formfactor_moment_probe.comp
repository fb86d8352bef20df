// Test probe (tests/HemisphereTest.cpp): formfactor_moment.glsl's kernelCentroid on given cases,
// to compare with brute-force quadrature. Case i: 7 vec4s in SSBO_PROBE_IN: x, n, the quad's unit
// front normal, then its corners a b c d (counter-clockwise around it); out: ybar, F.
#include "hemisphere.glsl"
#include "formfactor.glsl"
#include "formfactor_moment.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = SSBO_PROBE_IN) readonly buffer In { vec4 cases[]; };
layout(std430, binding = SSBO_PROBE_OUT) writeonly buffer Out { vec4 result[]; };

void main() {
  uint i = gl_GlobalInvocationID.x, b = i * 7u;
  vec3 ybar;
  float F = kernelCentroid(cases[b].xyz, cases[b + 1u].xyz, cases[b + 3u].xyz, cases[b + 4u].xyz, cases[b + 5u].xyz,
                           cases[b + 6u].xyz, cases[b + 2u].xyz, ybar);
  result[i] = vec4(ybar, F);
}
