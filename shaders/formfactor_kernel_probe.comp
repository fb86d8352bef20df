// Test probe (tests/HemisphereTest.cpp): formfactor.glsl's pointToPolygon on given cases, to
// compare with its double twin cpu::pointToPolygon. Case i: 3 vec4s in SSBO_PROBE_IN: x, n, front
// normal; its shape in slot i of SSBO_SHOOTER_SHAPES (formfactor.glsl's layout).
#include "hemisphere.glsl"
#include "formfactor.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = SSBO_PROBE_IN) readonly buffer In { vec4 cases[]; };
layout(std430, binding = SSBO_PROBE_OUT) writeonly buffer Out { float result[]; };

void main() {
  uint i = gl_GlobalInvocationID.x, base = i * 3u;
  result[i] = pointToPolygon(cases[base].xyz, cases[base + 1u].xyz, i, cases[base + 2u].xyz);
}
