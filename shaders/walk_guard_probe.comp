// Test probe (tests/WalkGuardGLTest.cpp): `turns` turns of a loop, then one segment walk through
// the BVH (bvh_segment.glsl); writes the turns the loop ran and whether the segment was blocked.
#include "scene.glsl"
#include "segment.glsl"
#include "bvh.glsl"
#include "bvh_segment.glsl"

layout(local_size_x = 1) in;
layout(std430, binding = SSBO_PROBE_OUT) writeonly buffer Out { uvec2 result; };
uniform uint turns;
uniform vec3 from, to;

void main() {
  uint ran = 0u;
  // Each turn adds 1 (a polygon has 3 or more vertices) through a load, which no compiler folds.
  for (uint i = 0u; i < turns; ++i) ran += uint(polygons[i & 3u].vertices.y >= 3u);
  result = uvec2(ran, segmentBlocked(from, to, NO_POLYGON, NO_POLYGON, 1e-4) ? 1u : 0u);
}
