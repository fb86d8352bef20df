// One level of the shooter reduction for large scenes: each workgroup folds 1024 entries.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "reduce_entry.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = 4) writeonly buffer Out { Entry dst[]; };

void main() {
  uint first = gl_WorkGroupID.x * 1024u;
  reduceGroup(first, min(first + 1024u, count));
  if (gl_LocalInvocationID.x == 0u) dst[gl_WorkGroupID.x] = partial[0];
}
