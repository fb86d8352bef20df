// One level of the shooter reduction for large scenes: each workgroup ranks 1024 entries and
// hands on its best `keep`, the first of them carrying the group's power sum.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "shooter_tree.glsl"
#include "reduce_entry.glsl"
#include "linear_group.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = SSBO_REDUCE_OUT) writeonly buffer Out { Entry dst[]; };

void main() {
  uint group = linearGroup(), first = group * GROUP_ENTRIES;
  if (first >= count) return;  // past the count in the tiled grid: the whole group leaves
  rankGroup(first, min(first + GROUP_ENTRIES, count));
  uint l = gl_LocalInvocationID.x;
  if (l < keep) dst[group * keep + l] = Entry(rankPower[l], rankIndex[l], l == 0u ? groupSum[0] : 0.0, 0.0);
}
