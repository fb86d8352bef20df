// One batch of VPLs at a surface point (seed 002 §3: every light's weighted contribution), shared
// by forward and deferred shading so both compute the same sums in the same order. The VPL is a
// Lambertian point emitter of flux Phi: irradiance Phi cos_v cos_x / (pi r^2). The geometry term
// cos_v cos_x / r^2 is clamped at maxGeometry (the 1/r^2 singularity); what the clamp removes goes
// to alpha, so the image itself carries the clamp's bias.
// Interleaved sampling (Keller & Heidrich 2001): with interleaveM = n^2 > 1 a pixel sums only
// its subset of the VPLs (index = subset mod M), times M; instant_filter.comp then averages the
// n x n tile, which holds every subset once. M = 1 is the exact sum over every VPL.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "vpl.glsl"
#include "segment.glsl"

layout(binding = SAMPLER_SHADOW_ID) uniform usampler2DArray shadowId;
uniform uint vplFirst, vplCount;
uniform uint interleaveM;  // n^2 VPL subsets
uniform float maxGeometry;
uniform float farDistance;
uniform bool addEmission;  // the first batch adds E
// The camera ray through window point w (pixel centres at .5) is eye + t (rayCorner + w.x rayDx +
// w.y rayDy), set from the camera on the CPU in double.
uniform vec3 eye, rayCorner, rayDx, rayDy;

// The point of `polygon` seen through window point w: its plane met by the pixel's ray. Exact to
// float rounding, where an interpolated position carries the rasterizer's own error too.
vec3 surfacePoint(vec2 w, uint polygon) {
  vec3 dir = rayCorner + w.x * rayDx + w.y * rayDy;
  vec4 plane = polygons[polygon].normal;
  return eye + dir * ((plane.w - dot(plane.xyz, eye)) / dot(plane.xyz, dir));
}

// Whether x (on `polygon`) is seen from VPL v (its shadow map: layer i). As the gather's
// visibility (visibility.glsl), the map only nominates the occluder: the polygon nearest along
// x's pixel is tested exactly against the segment VPL -> x. A depth comparison instead needs a
// bias, and fails where a face seen edge-on (a block's side from a ceiling light) shares its
// pixels with a nearer face (the block's top): the side went dark. What this can miss: an
// occluder whose edge crosses x's pixel without covering its centre (shadow edges, to a pixel).
float vplVisibility(int i, uint v, vec3 x, vec3 local, uint polygon) {
  ivec2 size = textureSize(shadowId, 0).xy;
  uint q = texelFetch(shadowId, ivec3(itemTexel(local, size).xy, i), 0).r;
  if (q == polygon || q == NO_POLYGON) return 1.0;
  return blocksSegment(q, vpl[v].position.xyz, x, SEGMENT_TOLERANCE * farDistance) ? 0.0 : 1.0;
}

// The VPL subset of pixel p under n x n interleaving: its place in the tile.
uint pixelSubset(uvec2 p, uint n) { return p.x % n + n * (p.y % n); }

vec4 shadeBatch(vec3 x, uint polygon, uint subset) {
  vec3 n = polygons[polygon].normal.xyz, rho = polygons[polygon].reflectance.rgb;
  vec3 sum = vec3(0.0);
  float removed = 0.0;
  for (uint k = (subset + interleaveM - vplFirst % interleaveM) % interleaveM; k < vplCount; k += interleaveM) {
    uint v = vplFirst + k;
    vec3 flux = vpl[v].flux.rgb;
    vec3 d = vpl[v].position.xyz - x;
    float r2 = dot(d, d);
    float cx = dot(n, d), cv = -dot(vpl[v].normal.xyz, d);
    if (cx <= 0.0 || cv <= 0.0 || flux == vec3(0.0)) continue;
    vec3 local = shooterLocal(x, vpl[v].position.xyz, vpl[v].normal.xyz);
    if (vplVisibility(int(k), v, x, local, polygon) == 0.0) continue;
    float g = cx * cv / (r2 * r2);
    float clamped = min(g, maxGeometry);
    sum += flux * clamped;
    removed += luminance(rho * flux) * (g - clamped);
  }
  float m = float(interleaveM);
  vec3 b = rho * (sum * m) / PI;
  if (addEmission) b += polygons[polygon].emission.rgb;
  return vec4(b, removed * m / PI);
}
