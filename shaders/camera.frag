// Bilinear lookup of B that only weighs texels of the fragment's own chart, so charts never
// bleed into each other, a chart's polygons (a tessellated wall) blend across their edges, and
// partial edge texels are used as they are. Its CPU twin is Atlas::sample.
#include "scene.glsl"
#ifdef PER_PIXEL_DIRECT
// --direct per-pixel (src/output/DirectLight.h): the atlas holds the indirect part only; a first
// pass shows E + indirect, a second over the same depths (GL_EQUAL) adds each pixel's direct light
// (and with --final-gather near the near field's correction, near_gather.glsl).
#include "hemisphere.glsl"
#include "formfactor.glsl"
#include "segment.glsl"
#include "bvh.glsl"
#include "bvh_segment.glsl"
#include "direct.glsl"
#ifdef NEAR_GATHER
#include "shooter_tree.glsl"
#include "near_gather.glsl"
#endif
centroid in vec3 vPosition, vNormal;
uniform bool directPass;
#endif

layout(binding = SAMPLER_ATLAS_VALUES) uniform sampler2D radiosity;
// Seed 004's display-only ambient term (ambient.comp): rho_j A is added to what is shown.
layout(std430, binding = SSBO_AMBIENT) readonly buffer Ambient { vec4 ambient; };
uniform bool addAmbient;
centroid in vec2 vAtlas;
flat in uint vPolygon;
layout(location = 0) out vec4 color;

#ifdef PER_PIXEL_DIRECT
// p (on its polygon's plane) kept inside its convex polygon, clear of each edge by 1e-4 of its
// length. A partly covered cell's shading point can fall on or past its polygon's edge (on
// llvmpipe, centroid interpolation along a crease), where a crease's other wall is seen edge-on
// or from behind and the form factors to it vanish (the furnace: 6-12 % dark pixels along its
// diagonal crease); a pixel centre that a symmetric view puts on a crease line, as well.
vec3 insidePolygon(vec3 p, uint polygon) {
  uvec4 v = polygons[polygon].vertices;
  vec3 n = polygons[polygon].normal.xyz;
  for (int pass = 0; pass < 2; ++pass)  // twice: a push off one edge may cross its neighbour
    for (uint i = 0u; i < v.y; ++i) {
      vec3 a = polygonVertex[v.x + i].xyz, b = polygonVertex[v.x + (i + 1u) % v.y].xyz;
      vec3 inward = normalize(cross(n, b - a));
      float clear = 1e-4 * length(b - a), d = dot(inward, p - a);
      if (d < clear) p += (clear - d) * inward;
    }
  return p;
}
#endif

// The texels the lookup blends at atlas coordinate a, their weights and the weights' sum (0: no
// texel of the chart near).
float lookUp(vec2 a, uint chart, out ivec2 texel[4], out float weight[4], out int count) {
  vec2 c = a - 0.5;
  ivec2 i0 = ivec2(floor(c));
  vec2 f = c - vec2(i0);
  float total = 0.0;
  count = 0;
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    float w = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    if (chartAtTexel(i0 + o) == chart) texel[count] = i0 + o, weight[count++] = w, total += w;
  }
  if (total <= 0.0) {  // a sliver of the polygon whose own texel holds no element: nearest one
    count = 0;
    ivec2 centre = ivec2(floor(a));
    for (int k = 0; k < 9 && count == 0; ++k) {
      ivec2 t = centre + ivec2(k % 3 - 1, k / 3 - 1);
      if (chartAtTexel(t) == chart) texel[0] = t, weight[0] = total = 1.0, count = 1;
    }
  }
  return total;
}

void main() {
  ivec2 texel[4];
  float weight[4];
  int count;
  float total = lookUp(vAtlas, chartOf(vPolygon), texel, weight, count);
#ifdef PER_PIXEL_DIRECT
  if (directPass) {  // added to the first pass's colour
    // A curved chart's receivers take the smooth normal, as its elements do (Atlas::normalOf).
    vec3 n = vNormal == vec3(0.0) ? polygons[vPolygon].normal.xyz : normalize(vNormal);
    vec3 x = insidePolygon(vPosition, vPolygon);
    vec3 add = directLight(x, n, vPolygon);  // this draw's share of the emitter pieces
#ifdef NEAR_GATHER
    for (int k = 0; k < count; ++k) weight[k] /= total;
    add += polygons[vPolygon].reflectance.rgb *
           nearCorrection(ontoPlane(x, vPolygon), n, vPolygon, Lookup(texel, weight, count));
#endif
    color = vec4(add, 0.0);
    return;
  }
#endif
  vec3 b = vec3(0.0);
  for (int k = 0; k < count; ++k) b += weight[k] * texelFetch(radiosity, texel[k], 0).rgb;
  b = total > 0.0 ? b / total : vec3(0.0);
  if (addAmbient) b += polygons[vPolygon].reflectance.rgb * ambient.rgb;
#ifdef PER_PIXEL_DIRECT
  b += polygons[vPolygon].emission.rgb;  // E cancelled in B - B_direct (src/solver/DirectSplit.h)
#endif
  color = vec4(b, 1.0);
}
