// Seed 004's user-view item buffer, as counts: each visible pixel of the user's view adds one
// to the element (atlas texel) it shows. Drawn twice with camera.vert: a depth pass, then with
// depth EQUAL and countPixels, so only the nearest surface of each pixel counts.
#include "scene.glsl"

layout(early_fragment_tests) in;
layout(binding = IMAGE_VIEW_PIXELS, r32ui) uniform uimage2D pixels;
uniform bool countPixels;
in vec2 vAtlas;
flat in uint vPolygon;

void main() {
  if (!countPixels) return;
  ivec2 t = ivec2(floor(vAtlas));
  uint chart = chartOf(vPolygon);
  // A sliver of the chart whose own texel holds no element: the nearest texel that does.
  for (int k = 0; k < 9 && chartAtTexel(t) != chart; ++k)
    t = ivec2(floor(vAtlas)) + ivec2(k % 3 - 1, k / 3 - 1);
  if (chartAtTexel(t) == chart) imageAtomicAdd(pixels, t, 1u);
}
