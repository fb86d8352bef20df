// The luminance sum pyramid's layout (pyramid.comp builds it, sample.comp descends it): level l
// is (pyramidSide >> l)^2 floats, row-major, stored after the finer levels.
layout(std430, binding = SSBO_PYRAMID) buffer Pyramid { float pyramid[]; };
uniform uint pyramidSide;  // level 0's side, a power of two >= the atlas's sides

uint pyramidOffset(uint level) {
  uint offset = 0u;
  for (uint l = 0u; l < level; ++l) offset += (pyramidSide >> l) * (pyramidSide >> l);
  return offset;
}

// The four children of node t (one level up from `childLevel`), in the order they are summed.
void children(uint childLevel, uvec2 t, out float c[4]) {
  uint side = pyramidSide >> childLevel, base = pyramidOffset(childLevel);
  for (uint i = 0u; i < 4u; ++i) {
    uvec2 q = 2u * t + uvec2(i & 1u, i >> 1u);
    c[i] = pyramid[base + q.y * side + q.x];
  }
}

float childSum(uint childLevel, uvec2 t) {
  float c[4];
  children(childLevel, t, c);
  return (c[0] + c[1]) + (c[2] + c[3]);
}
