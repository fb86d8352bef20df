// The camera's multisample resolve: each pixel the plain mean of its samples (a box filter, as
// the supersample grid's; the driver's own resolve may weight them), summed pairwise so that
// equal samples (a pixel no edge crosses: its one fragment's colour) give that colour exactly.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = SAMPLER_MULTISAMPLE) uniform sampler2DMS samples;
layout(binding = IMAGE_RESOLVED, rgba32f) writeonly uniform image2D resolved;
uniform int sampleCount;  // a power of two, at most MAX_CAMERA_SAMPLES

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(resolved)))) return;
  vec4 s[MAX_CAMERA_SAMPLES];
  for (int i = 0; i < sampleCount; ++i) s[i] = texelFetch(samples, p, i);
  for (int n = sampleCount / 2; n >= 1; n /= 2)
    for (int i = 0; i < n; ++i) s[i] = s[2 * i] + s[2 * i + 1];
  imageStore(resolved, p, s[0] / float(sampleCount));
}
