// One level of the luminance sum pyramid (a quadtree over the atlas, padded to a power of two):
// level 0 holds luminance(B) x area per texel, level l + 1 the sum of each 2 x 2 of level l,
// summed as (c0 + c1) + (c2 + c3), the order pyramid.glsl's descent re-adds them in, so a
// parent equals its children's sum bit for bit. Levels are packed finest first in one SSBO.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "pyramid.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) readonly uniform image2D radiosity;
uniform uint level;
uniform ivec2 atlasSize;

void main() {
  uint side = pyramidSide >> level;
  uvec2 t = gl_GlobalInvocationID.xy;
  if (t.x >= side || t.y >= side) return;
  float value = 0.0;
  if (level == 0u) {
    ivec2 a = ivec2(t);
    if (all(lessThan(a, atlasSize)) && texelFetch(atlasPolygon, a, 0).r != NO_POLYGON)
      value = max(luminance(imageLoad(radiosity, a).rgb), 0.0) * texelFetch(atlasPositionArea, a, 0).w;
  } else {
    value = childSum(level - 1u, t);
  }
  pyramid[pyramidOffset(level) + t.y * side + t.x] = value;
}
