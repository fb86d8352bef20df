// Visibility of a receiver element from a shooter of the pass, looked up in the item buffer.
// Needs hemisphere.glsl and control.glsl. Texture units 2 (polygon ids) and 3 (depth =
// distance / far), ITEM_FACES layers per shooter.

layout(binding = 2) uniform usampler2DArray itemId;
layout(binding = 3) uniform sampler2DArray itemDepth;
uniform float farDistance;

// The element's centre (`local`: in the shooter's frame) is projected into the shooter's item
// buffer and the pixel under it read (point sampling, no filtering):
//  - the pixel shows the element's own polygon: visible;
//  - it shows another surface that is not nearer than the element by more than one element
//    size (a neighbour across an edge, a corner, or nothing at all near the hemisphere rim,
//    where the clipped item mesh leaves pixels empty): visible;
//  - otherwise something nearer hides it: hidden.
// So a partially hidden element is all-or-nothing, decided at its centre.
float visibility(uint shooter, vec3 local, uint polygon, float elementSize) {
  ivec3 texel = itemTexel(local, textureSize(itemId, 0).xy) + ivec3(0, 0, int(shooter) * ITEM_FACES);
  if (texelFetch(itemId, texel, 0).r == polygon) return 1.0;
  float seen = texelFetch(itemDepth, texel, 0).r * farDistance;
  return seen >= length(local) - elementSize ? 1.0 : 0.0;
}

// Receiver texel t (of `polygon`) lies in the block of shooter s: coplanar, it receives nothing.
bool inShooterBlock(uint s, ivec2 t, uint polygon) {
  ivec4 r = control.shooter[s].rect;
  return polygon == control.shooter[s].polygon && all(greaterThanEqual(t, r.xy)) && all(lessThan(t, r.xy + r.zw));
}

// Form factor from receiver element t (of `polygon`) to shooter s of the pass, visibility
// included: docs/design.md#form-factor's V max(cos_s,0) max(cos_r,0) A_s / (pi r^2 + A_s). `facing` is false
// when the pair cannot exchange light (behind either surface); then the visibility is not
// looked up and `visible` is 0.
float shooterFormFactor(uint s, ivec2 t, uint polygon, out bool facing, out float visible) {
  vec4 pa = texelFetch(atlasPositionArea, t, 0);
  vec3 shooter = control.shooter[s].positionArea.xyz;
  vec3 n = control.shooter[s].normal.xyz;
  vec3 d = pa.xyz - shooter;
  float r2 = dot(d, d);
  vec3 w = d * inversesqrt(r2);
  float cosS = dot(n, w), cosR = -dot(polygons[polygon].normal.xyz, w);
  facing = cosS > 0.0 && cosR > 0.0;
  visible = facing ? visibility(s, shooterLocal(pa.xyz, shooter, n), polygon, sqrt(pa.w)) : 0.0;
  return visible * discFormFactor(cosS, cosR, r2, control.shooter[s].positionArea.w);
}
