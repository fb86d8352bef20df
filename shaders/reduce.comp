// One level of the shooter reduction for large scenes: each workgroup ranks 1024 entries and
// hands on its best `keep`, the first of them carrying the group's power sum.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "shooter_tree.glsl"
#include "reduce_entry.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = SSBO_REDUCE_OUT) writeonly buffer Out { Entry dst[]; };

void main() {
  uint first = gl_WorkGroupID.x * GROUP_ENTRIES;
  rankGroup(first, min(first + GROUP_ENTRIES, count));
  uint l = gl_LocalInvocationID.x;
  if (l < keep) dst[gl_WorkGroupID.x * keep + l] = Entry(rankPower[l], rankIndex[l], l == 0u ? groupSum[0] : 0.0, 0.0);
}
