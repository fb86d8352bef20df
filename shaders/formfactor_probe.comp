// Validation probe (src/validate/Validate.cpp): for one shooter (the first of the control block), every receiver element's item-buffer
// visibility and form factor, exactly as gather.comp computes them, written out instead of
// applied. r: visibility (0/1), g: F, b: 1 where the pair faces each other.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "control.glsl"
#include "formfactor.glsl"
#include "visibility.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_PROBE, rgba32f) uniform writeonly image2D probe;
uniform ivec2 atlasSize;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(t, atlasSize))) return;
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  if (polygon == NO_POLYGON || chartOf(polygon) == chartOf(control.shooter[0].polygon)) {
    imageStore(probe, t, vec4(0.0));
    return;
  }
  bool facing;
  float visible;
  float F = shooterFormFactor(0u, receiverAt(t, polygon), facing, visible);
  imageStore(probe, t, vec4(visible, F, facing ? 1.0 : 0.0, 0.0));
}
