// Unshot power luminance(dB) * A of every shooter block (one texel, or 2^k x 2^k texels of
// one chart with substructuring), as the first level of the argmax/sum reduction.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "reduce_entry.glsl"

layout(local_size_x = 64) in;
layout(binding = 1, rgba32f) uniform readonly image2D deltaB;
layout(std430, binding = 1) readonly buffer Blocks { ivec4 blockRect[]; };
layout(std430, binding = 2) writeonly buffer Out { Entry entries[]; };
uniform uint blockCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= blockCount) return;
  ivec4 r = blockRect[i];
  float power = 0.0;
  for (int y = r.y; y < r.y + r.w; ++y)
    for (int x = r.x; x < r.x + r.z; ++x)
      power += luminance(imageLoad(deltaB, ivec2(x, y)).rgb) * texelFetch(atlasPositionArea, ivec2(x, y), 0).w;
  entries[i] = Entry(power, i, power, 0.0);
}
