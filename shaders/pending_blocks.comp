// Seed 004 §5.5.2's shooting-locations vector: the blocks with table entries for the surfaces
// of a delivery round, i.e. that shot between the epochs one of those surfaces' entries start
// and end at, each with the power of its largest entry (luminance x block area), so the
// strongest are delivered first.
#include "hemisphere.glsl"
#include "shooter_tree.glsl"
#include "linear_group.glsl"

layout(local_size_x = 256) in;
layout(std430, binding = SSBO_SNAPSHOTS) readonly buffer Snapshots { vec4 snapshot[]; };
layout(std430, binding = SSBO_PENDING) writeonly buffer Pending { float pending[]; };
layout(std430, binding = SSBO_SPANS) readonly buffer Spans { uvec2 spans[]; };  // (start, end) epochs
uniform uint blockCount;
uniform uint spanCount;

void main() {
  uint b = linearInvocation(gl_WorkGroupSize.x);
  if (b >= blockCount) return;
  bool any = false;
  float most = 0.0;
  for (uint k = 0u; k < spanCount; ++k) {
    vec3 entry = snapshot[spans[k].y * blockCount + b].rgb - snapshot[spans[k].x * blockCount + b].rgb;
    any = any || entry != vec3(0.0);
    most = max(most, luminance(entry) * nodes[b].centreArea.w);
  }
  pending[b] = any ? max(most, 1e-30) : 0.0;  // 0: nothing to deliver
}
