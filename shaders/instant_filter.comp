// Interleaved sampling's geometry-aware filter (the discontinuity buffer of Keller & Heidrich
// 2001): a pixel averages the n x n window around it (every VPL subset once), over the pixels
// of its own polygon only. hemirad's polygons are flat and of one material, so the polygon id
// is an exact discontinuity test: light never blurs across an edge or onto another surface. A
// pixel whose window leaves its polygon averages fewer subsets (each unbiased, noisier).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SAMPLER_G_POLYGON) uniform usampler2D gPolygon;  // polygon id + 1 (0: background)
layout(rgba32f, binding = IMAGE_SHADED) readonly uniform image2D shaded;
layout(rgba32f, binding = IMAGE_FILTERED) writeonly uniform image2D filtered;
uniform uint interleave;
uniform ivec2 sub;           // de-interleaved blocks' size
uniform bool deinterleaved;  // `shaded` is in blocks (deferred) or image order (forward)

ivec2 stored(ivec2 p, int n) { return deinterleaved ? (p % n) * sub + p / n : p; }

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy), size = textureSize(gPolygon, 0);
  if (any(greaterThanEqual(p, size))) return;
  uint id = texelFetch(gPolygon, p, 0).r;
  int n = int(interleave), lo = -(n / 2);
  vec4 sum = vec4(0.0);
  float count = 0.0;
  for (int dy = lo; dy < lo + n; ++dy)
    for (int dx = lo; dx < lo + n; ++dx) {
      ivec2 r = p + ivec2(dx, dy);
      if (any(lessThan(r, ivec2(0))) || any(greaterThanEqual(r, size))) continue;
      if (texelFetch(gPolygon, r, 0).r != id) continue;
      sum += imageLoad(shaded, stored(r, n));
      count += 1.0;
    }
  imageStore(filtered, p, id == 0u ? vec4(0.0) : sum / count);
}
