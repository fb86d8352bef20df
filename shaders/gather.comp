// One pass, gathered at every receiver texel (seed 003 §39.2): for each shooter of the pass,
// visibility from its item buffer, the disc form factor, and B += rho dB_s F, dB += rho dB_s F.
// A shooter block's own dB is reset here (its texels are coplanar with it and receive nothing
// from it, but do receive from the pass's other shooters).
#include "hemisphere.glsl"
#include "scene.glsl"
#include "control.glsl"
#include "visibility.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0, rgba32f) uniform image2D radiosity;
layout(binding = 1, rgba32f) uniform image2D deltaB;
uniform ivec2 atlasSize;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (control.done != 0u || any(greaterThanEqual(t, atlasSize))) return;  // once stopped, passes are empty
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  if (polygon == NO_POLYGON) return;
  vec3 received = vec3(0.0);
  bool shot = false;
  for (uint s = 0u; s < control.count; ++s) {
    if (inShooterBlock(s, t, polygon)) {
      shot = true;
      continue;
    }
    bool facing;
    float visible;
    float F = shooterFormFactor(s, t, polygon, facing, visible);
    if (F > 0.0) received += control.shooter[s].deltaB.rgb * F;
  }
  if (!shot && received == vec3(0.0)) return;
  vec3 delta = polygons[polygon].reflectance.rgb * received;
  imageStore(radiosity, t, imageLoad(radiosity, t) + vec4(delta, 0.0));
  imageStore(deltaB, t, (shot ? vec4(0.0) : imageLoad(deltaB, t)) + vec4(delta, 0.0));
}
