// One level of the argmax + sum reduction: each workgroup folds 1024 entries into one, in a
// fixed tree order so the sum is bitwise reproducible.
#include "reduce_entry.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 2) readonly buffer In { Entry src[]; };
layout(std430, binding = 4) writeonly buffer Out { Entry dst[]; };
uniform uint count;
shared Entry partial[256];

void main() {
  uint base = gl_WorkGroupID.x * 1024u + gl_LocalInvocationID.x;
  Entry e = Entry(-1.0, 0xFFFFFFFFu, 0.0, 0.0);
  for (uint k = 0u; k < 4u; ++k) {
    uint i = base + k * 256u;
    if (i < count) e = combine(e, src[i]);
  }
  partial[gl_LocalInvocationID.x] = e;
  barrier();
  for (uint stride = 128u; stride > 0u; stride >>= 1) {
    if (gl_LocalInvocationID.x < stride)
      partial[gl_LocalInvocationID.x] = combine(partial[gl_LocalInvocationID.x], partial[gl_LocalInvocationID.x + stride]);
    barrier();
  }
  if (gl_LocalInvocationID.x == 0u) dst[gl_WorkGroupID.x] = partial[0];
}
