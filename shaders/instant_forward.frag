// Forward shading (seed 002's path): each VPL batch is a pass over the scene's triangles, depth
// equal to the pre-pass, added into the image.
#include "instant_shade.glsl"
in vec3 vPosition;
flat in uint vPolygon;
layout(location = 0) out vec4 color;
void main() { color = shadeBatch(vPosition, vPolygon); }
