// Forward shading (seed 002's path): each VPL batch is a pass over the scene's triangles, depth
// equal to the pre-pass, added into the image. Interleaved, a pixel's subset is its tile place.
// The point is found from the pixel as in deferred shading, so both paths shade the same points.
#include "instant_shade.glsl"
flat in uint vPolygon;
uniform uint interleave;
layout(location = 0) out vec4 color;
void main() {
  vec3 x = surfacePoint(gl_FragCoord.xy, vPolygon);
  color = shadeBatch(x, vPolygon, pixelSubset(uvec2(gl_FragCoord.xy), interleave));
}
