// Seed 004's ambient term (§4.1.6): A = R S, where S = sum_i dB_i A_i / sum_i A_i is the
// area-averaged unshot radiosity and R = 1 / (1 - rho_avg) its interreflection (per channel).
// Shown as B + rho_j A, never added to B. One workgroup in a fixed order: deterministic.
// View-driven solves (received importance W_i = I_i - R_i > 0 somewhere, alpha of B) average
// dB weighted by A_i W_i instead: the unshot light of the surfaces that light the view, not
// that of rooms nobody sees, which they leave unshot on purpose (issue 19: the plain average
// lit their views with it). With converged importance, R S is then sum_i dB_i A_i W_i / rho_avg,
// the light the view still misses.
#include "scene.glsl"

layout(local_size_x = 256) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) readonly uniform image2D radiosity;  // a: received importance I - R
layout(binding = IMAGE_DELTA_B, rgba32f) readonly uniform image2D deltaB;
layout(std430, binding = SSBO_AMBIENT) writeonly buffer Ambient { vec4 ambient; };
uniform vec3 interreflection;  // R
uniform float totalArea;

shared vec4 partial[256];   // sum dB A, sum A W
shared vec3 weighted[256];  // sum dB A W

void main() {
  ivec2 size = imageSize(deltaB);
  int n = size.x * size.y;
  vec4 sum = vec4(0.0);
  vec3 byImportance = vec3(0.0);
  for (int t = int(gl_LocalInvocationIndex); t < n; t += 256) {
    ivec2 p = ivec2(t % size.x, t / size.x);
    float area = texelFetch(atlasPositionArea, p, 0).w;
    vec3 unshot = imageLoad(deltaB, p).rgb * area;
    float importance = max(imageLoad(radiosity, p).a, 0.0);
    sum += vec4(unshot, area * importance);
    byImportance += unshot * importance;
  }
  partial[gl_LocalInvocationIndex] = sum;
  weighted[gl_LocalInvocationIndex] = byImportance;
  barrier();
  for (uint s = 128u; s > 0u; s >>= 1) {
    if (gl_LocalInvocationIndex < s) {
      partial[gl_LocalInvocationIndex] += partial[gl_LocalInvocationIndex + s];
      weighted[gl_LocalInvocationIndex] += weighted[gl_LocalInvocationIndex + s];
    }
    barrier();
  }
  if (gl_LocalInvocationIndex == 0u) {
    vec3 s = partial[0].w > 0.0 ? weighted[0] / partial[0].w : partial[0].rgb / totalArea;
    ambient = vec4(interreflection * s, 0.0);
  }
}
