// One shot, gathered at every receiver texel (seed 003 §39.2): visibility from the item
// buffer, the disc form factor, and B += rho dB_s F, dB += rho dB_s F. The shooter block's
// own dB is reset here; its texels are coplanar with the shooter and receive nothing.
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
  if (control.done != 0u || any(greaterThanEqual(t, atlasSize))) return;  // once stopped, shots are empty
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  if (polygon == NO_POLYGON) return;
  ivec4 r = control.shooterRect;
  if (polygon == control.shooterPolygon && all(greaterThanEqual(t, r.xy)) && all(lessThan(t, r.xy + r.zw))) {
    imageStore(deltaB, t, vec4(0.0));
    return;
  }
  bool facing;
  float visible;
  float F = shooterFormFactor(t, polygon, facing, visible);
  if (F <= 0.0) return;
  vec3 delta = polygons[polygon].reflectance.rgb * control.shooterDeltaB.rgb * F;
  imageStore(radiosity, t, imageLoad(radiosity, t) + vec4(delta, 0.0));
  imageStore(deltaB, t, imageLoad(deltaB, t) + vec4(delta, 0.0));
}
