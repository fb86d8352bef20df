// Seed 004 §5.5.3: the pass's shooters are table columns, blocks that shot while surfaces now
// becoming visible were out of view; gather.comp (viewMode 2) hands each receiver its entry.
#include "scene.glsl"
#include "control.glsl"
#include "shooter_tree.glsl"
#include "shooter_block.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = SSBO_DEFERRED_BLOCKS) readonly buffer Deferred { uint deferredBlock[]; };
uniform uint first;
uniform uint count;

void main() {
  uint l = gl_GlobalInvocationID.x;
  if (l == 0u) control.count = count, control.importanceCount = 0u;
  if (l >= count) return;
  uint b = deferredBlock[first + l];
  describeNode(l, b, b);
}
