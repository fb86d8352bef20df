// Bilinear lookup of B that only weighs texels of the fragment's own chart, so charts never
// bleed into each other, a chart's polygons (a tessellated wall) blend across their edges, and
// partial edge texels are used as they are. Its CPU twin is Atlas::sample.
#include "scene.glsl"
#ifdef PER_PIXEL_DIRECT
// --direct per-pixel (src/output/DirectLight.h): the atlas holds the indirect part only; a first
// pass shows E + indirect, a second over the same depths (GL_EQUAL) adds each pixel's direct light.
#include "hemisphere.glsl"
#include "formfactor.glsl"
#include "segment.glsl"
#include "bvh.glsl"
#include "bvh_segment.glsl"
#include "direct.glsl"
in vec3 vPosition;
uniform bool directPass;
#endif

layout(binding = SAMPLER_ATLAS_VALUES) uniform sampler2D radiosity;
// Seed 004's display-only ambient term (ambient.comp): rho_j A is added to what is shown.
layout(std430, binding = SSBO_AMBIENT) readonly buffer Ambient { vec4 ambient; };
uniform bool addAmbient;
in vec2 vAtlas;
flat in uint vPolygon;
layout(location = 0) out vec4 color;

void main() {
#ifdef PER_PIXEL_DIRECT
  if (directPass) {
    color = vec4(directLight(vPosition, vPolygon), 0.0);  // added to the first pass's colour
    return;
  }
#endif
  uint chart = chartOf(vPolygon);
  vec2 c = vAtlas - 0.5;
  ivec2 i0 = ivec2(floor(c));
  vec2 f = c - vec2(i0);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    if (chartAtTexel(i0 + o) == chart) {
      sum += w * texelFetch(radiosity, i0 + o, 0).rgb;
      weight += w;
    }
  }
  if (weight <= 0.0) {  // a sliver of the polygon whose own texel holds no element: nearest one
    ivec2 centre = ivec2(floor(vAtlas));
    for (int k = 0; k < 9 && weight <= 0.0; ++k) {
      ivec2 t = centre + ivec2(k % 3 - 1, k / 3 - 1);
      if (chartAtTexel(t) == chart) sum = texelFetch(radiosity, t, 0).rgb, weight = 1.0;
    }
  }
  vec3 b = weight > 0.0 ? sum / weight : vec3(0.0);
  if (addAmbient) b += polygons[vPolygon].reflectance.rgb * ambient.rgb;
#ifdef PER_PIXEL_DIRECT
  b += polygons[vPolygon].emission.rgb;  // E cancelled in B - B_direct (src/solver/DirectSplit.h)
#endif
  color = vec4(b, 1.0);
}
