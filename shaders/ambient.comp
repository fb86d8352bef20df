// Seed 004's ambient term (§4.1.6): A = R S, where S = sum_i dB_i A_i / sum_i A_i is the
// area-averaged unshot radiosity and R = 1 / (1 - rho_avg) its interreflection (per channel).
// Shown as B + rho_j A, never added to B. One workgroup in a fixed order: deterministic.
#include "scene.glsl"

layout(local_size_x = 256) in;
layout(binding = 1, rgba32f) readonly uniform image2D deltaB;
layout(std430, binding = 5) writeonly buffer Ambient { vec4 ambient; };
uniform vec3 interreflection;  // R
uniform float totalArea;

shared vec3 partial[256];

void main() {
  ivec2 size = imageSize(deltaB);
  int n = size.x * size.y;
  vec3 sum = vec3(0.0);
  for (int t = int(gl_LocalInvocationIndex); t < n; t += 256) {
    ivec2 p = ivec2(t % size.x, t / size.x);
    sum += imageLoad(deltaB, p).rgb * texelFetch(atlasPositionArea, p, 0).w;
  }
  partial[gl_LocalInvocationIndex] = sum;
  barrier();
  for (uint s = 128u; s > 0u; s >>= 1) {
    if (gl_LocalInvocationIndex < s) partial[gl_LocalInvocationIndex] += partial[gl_LocalInvocationIndex + s];
    barrier();
  }
  if (gl_LocalInvocationIndex == 0u) ambient = vec4(interreflection * partial[0] / totalArea, 0.0);
}
