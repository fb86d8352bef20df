// Adaptive subdivision's test (seed 003 section 39.3.2, after Vedel and Puech 1991): per texel the
// radiosity's gradient, not its value (linear interpolation is not over-refined), as central
// differences over the texel's chart neighbours (one-sided at a chart's edge) in luminance per
// cell, relative to the texel's own luminance (floored: dark corners are not refined for noise).
// Texels over `threshold` count toward their leaf: an atomic counter per leaf stands for the
// seed's occlusion query. The CPU twin is src/solver/Subdivide.cpp's steepTexels.
#include "hemisphere.glsl"
#include "scene.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) readonly uniform image2D radiosity;
layout(std430, binding = SSBO_LEAF_OF) readonly buffer LeafOf { int leafOf[]; };
layout(std430, binding = SSBO_LEAF_COUNTS) buffer LeafCounts { uint leafCount[]; };
uniform float threshold;    // relative change per cell
uniform float darkest;      // the luminance floor under the relative change

// The luminance of texel t if it is an element of `chart`, else -1.
float lumIn(ivec2 t, uint chart) {
  if (chartAtTexel(t) != chart || texelFetch(atlasPositionArea, t, 0).w <= 0.0) return -1.0;
  return luminance(imageLoad(radiosity, t).rgb);
}

// The change per cell along `axis`: central where both neighbours are the chart's, else one-sided.
float change(ivec2 t, ivec2 axis, uint chart, float here) {
  float lo = lumIn(t - axis, chart), hi = lumIn(t + axis, chart);
  if (lo >= 0.0 && hi >= 0.0) return 0.5 * (hi - lo);
  if (hi >= 0.0) return hi - here;
  if (lo >= 0.0) return here - lo;
  return 0.0;
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy), size = imageSize(radiosity);
  if (t.x >= size.x || t.y >= size.y) return;
  int leaf = leafOf[t.y * size.x + t.x];
  if (leaf < 0) return;
  uint chart = chartAtTexel(t);
  float here = luminance(imageLoad(radiosity, t).rgb);
  float dx = change(t, ivec2(1, 0), chart, here), dy = change(t, ivec2(0, 1), chart, here);
  if (sqrt(dx * dx + dy * dy) > threshold * max(here, darkest)) atomicAdd(leafCount[leaf], 1u);
}
