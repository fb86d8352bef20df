// The area of interest beyond the simulated field of view (issue 19): a surface whose light the
// view needs, its received importance I - R (alpha of B) above `threshold` somewhere, receives radiosity
// too, so the light the view gets by way of surfaces out of view (the ceiling over the camera,
// the wall behind it) is not held back. All writes store 1: order does not matter.
#include "scene.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) uniform readonly image2D radiosity;
layout(std430, binding = SSBO_SEEN) writeonly buffer Seen { uint seen[]; };
uniform float threshold;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, imageSize(radiosity)))) return;
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  if (polygon != NO_POLYGON && imageLoad(radiosity, t).a > threshold) seen[polygon] = 1u;
}
