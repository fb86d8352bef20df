// The shooter reduction: argmax of unshot power over shooter blocks, and its sum (for the
// convergence), folded in a fixed tree order so both are bitwise reproducible.
// Needs scene.glsl and hemisphere.glsl (luminance) included first. Local size must be 256.

struct Entry {
  float best;   // largest power
  uint index;   // its block; ties go to the lower index, so the choice is deterministic
  float sum;    // total unshot power
  float pad;
};

layout(std430, binding = 1) readonly buffer Blocks { ivec4 blockRect[]; };  // atlas x, y, w, h
layout(std430, binding = 2) readonly buffer In { Entry src[]; };
layout(binding = 1, rgba32f) uniform readonly image2D deltaB;
uniform uint count;       // entries (or blocks) to fold
uniform bool fromBlocks;  // first level: compute the entries from the blocks

Entry combine(Entry a, Entry b) {
  bool takeB = b.best > a.best || (b.best == a.best && b.index < a.index);
  return Entry(takeB ? b.best : a.best, takeB ? b.index : a.index, a.sum + b.sum, 0.0);
}

// Unshot power luminance(dB) * A of one block (a texel, or 2^k x 2^k texels with substructuring).
float blockPower(ivec4 r) {
  float power = 0.0;
  for (int y = r.y; y < r.y + r.w; ++y)
    for (int x = r.x; x < r.x + r.z; ++x)
      power += luminance(imageLoad(deltaB, ivec2(x, y)).rgb) * texelFetch(atlasPositionArea, ivec2(x, y), 0).w;
  return power;
}

Entry loadEntry(uint i) {
  if (!fromBlocks) return src[i];
  float p = blockPower(blockRect[i]);
  return Entry(p, i, p, 0.0);
}

shared Entry partial[256];

// Folds entries first, first + 256, ... below end, one per thread, then the workgroup's 256
// partial results; the result is in partial[0] for every thread.
void reduceGroup(uint first, uint end) {
  Entry e = Entry(-1.0, 0xFFFFFFFFu, 0.0, 0.0);
  for (uint i = first + gl_LocalInvocationID.x; i < end; i += 256u) e = combine(e, loadEntry(i));
  partial[gl_LocalInvocationID.x] = e;
  barrier();
  for (uint stride = 128u; stride > 0u; stride >>= 1) {
    if (gl_LocalInvocationID.x < stride)
      partial[gl_LocalInvocationID.x] = combine(partial[gl_LocalInvocationID.x], partial[gl_LocalInvocationID.x + stride]);
    barrier();
  }
}
