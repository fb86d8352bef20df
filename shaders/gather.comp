// One shot, gathered at every receiver texel (seed 003 §39.2): visibility from the item
// buffer, the disc form factor, and B += rho dB_s F, dB += rho dB_s F. The shooter block's
// own dB is reset here; its texels are coplanar with the shooter and receive nothing.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "control.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0, rgba32f) uniform image2D radiosity;
layout(binding = 1, rgba32f) uniform image2D deltaB;
layout(binding = 2) uniform usampler2D itemId;
layout(binding = 3) uniform sampler2D itemDepth;
uniform ivec2 atlasSize;
uniform float farDistance;

// Visibility of a receiver element from the shooter. The element's centre is projected into
// the item buffer and the pixel under it read (point sampling, no filtering):
//  - the pixel shows the element's own polygon: visible;
//  - it shows another surface that is not nearer than the element by more than one element
//    size (a neighbour across an edge, a corner, or nothing at all near the hemisphere rim,
//    where the clipped item mesh leaves pixels empty): visible;
//  - otherwise something nearer hides it: hidden.
// So a partially hidden element is all-or-nothing, decided at its centre.
float visibility(vec3 local, uint polygon, float elementSize) {
  ivec2 size = textureSize(itemId, 0);
  vec2 uv = (hemiProject(local) * 0.5 + 0.5) * vec2(size);
  ivec2 pixel = clamp(ivec2(floor(uv)), ivec2(0), size - 1);
  if (texelFetch(itemId, pixel, 0).r == polygon) return 1.0;
  float seen = texelFetch(itemDepth, pixel, 0).r * farDistance;
  return seen >= length(local) - elementSize ? 1.0 : 0.0;
}

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, atlasSize))) return;
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  if (polygon == NO_POLYGON) return;
  ivec4 r = control.shooterRect;
  if (polygon == control.shooterPolygon && all(greaterThanEqual(t, r.xy)) && all(lessThan(t, r.xy + r.zw))) {
    imageStore(deltaB, t, vec4(0.0));
    return;
  }
  vec4 pa = texelFetch(atlasPositionArea, t, 0);
  vec3 shooter = control.shooterPositionArea.xyz;
  vec3 n = control.shooterNormal.xyz;
  vec3 d = pa.xyz - shooter;
  float r2 = dot(d, d);
  vec3 w = d * inversesqrt(r2);
  float cosS = dot(n, w), cosR = -dot(polygons[polygon].normal.xyz, w);
  if (cosS <= 0.0 || cosR <= 0.0) return;
  float v = visibility(shooterLocal(pa.xyz, shooter, n), polygon, sqrt(pa.w));
  if (v == 0.0) return;
  float F = v * discFormFactor(cosS, cosR, r2, control.shooterPositionArea.w);
  vec3 delta = polygons[polygon].reflectance.rgb * control.shooterDeltaB.rgb * F;
  imageStore(radiosity, t, imageLoad(radiosity, t) + vec4(delta, 0.0));
  imageStore(deltaB, t, imageLoad(deltaB, t) + vec4(delta, 0.0));
}
