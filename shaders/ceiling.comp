// Bench ceiling (src/bench/Bench.cpp): the gather's memory pattern without its maths, one RGBA32F
// texel loaded and stored per invocation, to measure the invocations/s a GPU can reach.
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = IMAGE_CEILING_VALUES, rgba32f) uniform image2D values;

void main() {
  ivec2 t = ivec2(gl_GlobalInvocationID.xy);
  imageStore(values, t, imageLoad(values, t) * 0.5 + vec4(1.0));
}
