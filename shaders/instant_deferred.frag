// Deferred shading (seed 002's faster path): a full-screen pass per VPL batch over the G-buffer.
#include "instant_shade.glsl"
layout(binding = 6) uniform sampler2D gPosition;
layout(location = 0) out vec4 color;
void main() {
  vec4 g = texelFetch(gPosition, ivec2(gl_FragCoord.xy), 0);
  if (g.w == 0.0) discard;
  color = shadeBatch(g.xyz, uint(g.w) - 1u);
}
