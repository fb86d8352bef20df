// Deferred shading (seed 002's faster path) in a compute shader, one dispatch per VPL batch over
// the G-buffer, added into the image. Compute, not a full-screen fragment pass: a compute GPU
// (H200) runs fragments on few of its SMs. Interleaved (n > 1) the image is shaded de-interleaved
// (Segovia et al. 2006): invocation q of block b = q / sub (b.x + n b.y: the subset) shades
// pixel (q mod sub) n + b, so a workgroup's invocations share their VPLs (coherent fetches);
// instant_filter.comp reads the blocks back in image order.
#include "instant_shade.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SAMPLER_G_POLYGON) uniform usampler2D gPolygon;  // polygon id + 1 (0: background)
layout(rgba32f, binding = IMAGE_SHADED) uniform image2D shaded;  // de-interleaved: n x n blocks of sub
uniform uint interleave;
uniform ivec2 sub;  // a block's size: ceil(image / n)

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy), n = ivec2(int(interleave));
  if (any(greaterThanEqual(q, sub * n))) return;
  ivec2 b = q / sub, p = (q % sub) * n + b;
  if (any(greaterThanEqual(p, textureSize(gPolygon, 0)))) return;  // padding of the last blocks
  uint id = texelFetch(gPolygon, p, 0).r;
  vec4 c = addEmission ? vec4(0.0) : imageLoad(shaded, q);
  if (id != 0u) c += shadeBatch(surfacePoint(vec2(p) + 0.5, id - 1u), id - 1u, uint(b.x + n.x * b.y));
  imageStore(shaded, q, c);
}
