// Surfaces seen by a view (seed 004 §5.3, with an id buffer instead of one occlusion query per
// surface): every pixel marks the polygon it shows. All writes store 1: order does not matter.
#include "scene.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_VIEW_IDS, r32ui) uniform readonly uimage2D ids;
layout(std430, binding = SSBO_SEEN) writeonly buffer Seen { uint seen[]; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(ids)))) return;
  uint id = imageLoad(ids, p).r;
  if (id != NO_POLYGON) seen[id] = 1u;
}
