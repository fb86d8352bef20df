// Visibility of a receiver element from the shooter, looked up in the item buffer.
// Needs hemisphere.glsl. Texture units 2 (polygon ids) and 3 (depth = distance / far).

layout(binding = 2) uniform usampler2DArray itemId;
layout(binding = 3) uniform sampler2DArray itemDepth;
uniform float farDistance;

// The element's centre (`local`: in the shooter's frame) is projected into the item buffer and
// the pixel under it read (point sampling, no filtering):
//  - the pixel shows the element's own polygon: visible;
//  - it shows another surface that is not nearer than the element by more than one element
//    size (a neighbour across an edge, a corner, or nothing at all near the hemisphere rim,
//    where the clipped item mesh leaves pixels empty): visible;
//  - otherwise something nearer hides it: hidden.
// So a partially hidden element is all-or-nothing, decided at its centre.
float visibility(vec3 local, uint polygon, float elementSize) {
  ivec3 texel = itemTexel(local, textureSize(itemId, 0).xy);
  if (texelFetch(itemId, texel, 0).r == polygon) return 1.0;
  float seen = texelFetch(itemDepth, texel, 0).r * farDistance;
  return seen >= length(local) - elementSize ? 1.0 : 0.0;
}

// Form factor from receiver element t (of `polygon`) to the current shooter (control.glsl),
// visibility included: DESIGN.md's V max(cos_s,0) max(cos_r,0) A_s / (pi r^2 + A_s).
// `facing` is false when the pair cannot exchange light (behind either surface); then the
// visibility is not looked up and `visible` is 0.
float shooterFormFactor(ivec2 t, uint polygon, out bool facing, out float visible) {
  vec4 pa = texelFetch(atlasPositionArea, t, 0);
  vec3 shooter = control.shooterPositionArea.xyz;
  vec3 n = control.shooterNormal.xyz;
  vec3 d = pa.xyz - shooter;
  float r2 = dot(d, d);
  vec3 w = d * inversesqrt(r2);
  float cosS = dot(n, w), cosR = -dot(polygons[polygon].normal.xyz, w);
  facing = cosS > 0.0 && cosR > 0.0;
  visible = facing ? visibility(shooterLocal(pa.xyz, shooter, n), polygon, sqrt(pa.w)) : 0.0;
  return visible * discFormFactor(cosS, cosR, r2, control.shooterPositionArea.w);
}
