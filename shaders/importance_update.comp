// Direct importance from the user's view (seed 004 §4.2.3, §4.2.6): R' = the fraction of the
// view's pixels showing the element, per unit of its area, and the change dR = R' - R added to
// the unshot importance dI (alpha of dB), so a camera move re-shoots only the difference. The
// alpha of B holds the importance received from other surfaces, I - R (what the element's
// light is worth to the view: the importance-driven key and the ambient's weight), so a move
// leaves it as it is.
#include "scene.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) uniform image2D radiosity;
layout(binding = IMAGE_DELTA_B, rgba32f) uniform image2D deltaB;
layout(binding = IMAGE_VIEW_PIXELS, r32ui) uniform readonly uimage2D pixels;
layout(binding = IMAGE_DIRECT, r32f) uniform image2D direct;
uniform ivec2 atlasSize;
uniform float viewPixels;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, atlasSize))) return;
  float area = texelFetch(atlasPositionArea, t, 0).w;
  if (area <= 0.0) return;
  float r = float(imageLoad(pixels, t).r) / (viewPixels * area);
  float dR = r - imageLoad(direct, t).r;
  if (dR == 0.0) return;
  imageStore(direct, t, vec4(r));
  imageStore(deltaB, t, imageLoad(deltaB, t) + vec4(0.0, 0.0, 0.0, dR));
}
