// Stochastic iteration's update (seed 000 eq. 2 and 3), at every receiver texel: the K
// one-texel shooters of the iteration, each with visibility from its item buffer and the exact
// form factor to its element, give received = sum_k shot_k V F; then the iterate and the mean
//   L <- emission E + rho received,  B <- (1 - weight) B + weight L.
// weight 1/m keeps B the running mean of the iterates; weight 1 with emission 0 applies the
// random operator once (the unbiasedness probe). The shooter's own texel receives nothing from
// it; the rest of its chart does (F = 0 on a plane, not on a concave curved chart), as in the
// progressive gather.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "control.glsl"
#include "formfactor.glsl"
#include "visibility.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) uniform image2D radiosity;
layout(binding = IMAGE_DELTA_B, rgba32f) writeonly uniform image2D iterate;
uniform ivec2 atlasSize;
uniform float weight, emission;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, atlasSize))) return;
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  if (polygon == NO_POLYGON) return;
  Receiver r = receiverAt(t, polygon);
  vec3 received = vec3(0.0);
  for (uint s = 0u; s < control.count; ++s) {
    if (control.shooter[s].polygon == NO_POLYGON || inShooterBlock(s, t, polygon)) continue;
    bool facing;
    float visible;
    float F = shooterFormFactor(s, r, facing, visible);
    if (F > 0.0) received += control.shooter[s].shot.rgb * F;
  }
  vec4 B = imageLoad(radiosity, t);
  vec3 next = emission * polygons[polygon].emission.rgb + polygons[polygon].reflectance.rgb * received;
  imageStore(radiosity, t, vec4((1.0 - weight) * B.rgb + weight * next, B.a));
  imageStore(iterate, t, vec4(next, 0.0));
}
