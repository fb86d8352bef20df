// Forward shading (seed 002's path): each VPL batch is a pass over the scene's triangles, depth
// equal to the pre-pass, added into the image. Interleaved, a pixel's subset is its tile place.
#include "instant_shade.glsl"
in vec3 vPosition;
flat in uint vPolygon;
uniform uint interleave;
layout(location = 0) out vec4 color;
void main() { color = shadeBatch(vPosition, vPolygon, pixelSubset(uvec2(gl_FragCoord.xy), interleave)); }
