// The element of texel t as its convex pieces in 3D: each chart part it is cut from (one per
// polygon of a curved chart, src/solver/TexelParts.h) clipped to the texel's prism along the
// chart's axis (what Atlas::elementShape computes in double on the CPU). Needs scene.glsl and
// formfactor.glsl (MAX_SHAPE_VERTICES). SSBO_CHARTS: per chart 4 vec4s: plane origin; u axis,
// w = texel size; v axis; lower-left corner of cell (0, 0) in plane coordinates (xy) and the
// chart's atlas origin (zw); then the parts' vertices. SSBO_TEXEL_PARTS: per texel its range of
// (first vertex, count) pairs.
layout(std430, binding = SSBO_CHARTS) readonly buffer Charts { vec4 chart[]; };
layout(std430, binding = SSBO_TEXEL_PARTS) readonly buffer TexelParts { uint texelPart[]; };

const int CLIP_VERTICES = MAX_SHAPE_VERTICES + 4;

// Keeps the part of v[0..n) where dot(p - o, axis) * side >= bound * side (one Sutherland-Hodgman step).
int clipAxis(inout vec3 v[CLIP_VERTICES], int n, vec3 o, vec3 axis, float bound, float side) {
  vec3 out_[CLIP_VERTICES];
  int m = 0;
  for (int i = 0; i < n; ++i) {
    vec3 p = v[i], q = v[(i + 1) % n];
    float dp = (dot(p - o, axis) - bound) * side, dq = (dot(q - o, axis) - bound) * side;
    if (dp >= 0.0 && m < CLIP_VERTICES) out_[m++] = p;
    if ((dp >= 0.0) != (dq >= 0.0) && m < CLIP_VERTICES) out_[m++] = p + (q - p) * (dp / (dp - dq));
  }
  for (int i = 0; i < m; ++i) v[i] = out_[i];
  return m;
}

// Part (first vertex, count) of chart c clipped to texel t's prism: the vertex count, 0 for a
// sliver, -1 when it does not fit MAX_SHAPE_VERTICES.
int clipPart(uint c, uvec2 part, ivec2 t, out vec3 shape[CLIP_VERTICES]) {
  if (part.y > uint(MAX_SHAPE_VERTICES)) return -1;
  int n = int(part.y);
  for (int i = 0; i < CLIP_VERTICES; ++i) shape[i] = i < n ? chart[part.x + uint(i)].xyz : vec3(0.0);
  vec3 o = chart[4u * c].xyz, u = chart[4u * c + 1u].xyz, v = chart[4u * c + 2u].xyz;
  float size = chart[4u * c + 1u].w;
  vec4 corner = chart[4u * c + 3u];
  vec2 lo = corner.xy + (vec2(t) - corner.zw) * size, hi = lo + size;
  n = clipAxis(shape, n, o, u, lo.x, 1.0);
  n = clipAxis(shape, n, o, u, hi.x, -1.0);
  n = clipAxis(shape, n, o, v, lo.y, 1.0);
  n = clipAxis(shape, n, o, v, hi.y, -1.0);
  return n < 3 ? 0 : n <= MAX_SHAPE_VERTICES ? n : -1;
}

void writePiece(uint base, int n, vec3 shape[CLIP_VERTICES]) {
  shooterShape[base] = vec4(float(n), 0.0, 0.0, 0.0);
  for (int i = 0; i < MAX_SHAPE_VERTICES; ++i) shooterShape[base + 1u + uint(i)] = vec4(shape[i], 1.0);
}

// Writes texel t's shape (of polygon `polygon`'s chart) as shooter k's: its first piece in slot
// k, the others from slot SHOOTER_SLOTS + k (MAX_TEXEL_PIECES - 1) on, each header linking the
// next (formfactor.glsl's pointToShape layout). Count 0 in slot k, the disc, when a piece or the piece count does not fit.
void writeTexelShape(uint k, uint polygon, ivec2 t, uint atlasWidth) {
  uint c = polygons[polygon].vertices.z, at = uint(t.y) * atlasWidth + uint(t.x);
  uint from = texelPart[at], to = texelPart[at + 1u], extra = SHOOTER_SLOTS + k * (MAX_TEXEL_PIECES - 1u);
  vec3 shape[CLIP_VERTICES];
  uint pieces = 0u, previous = 0u;
  bool fits = to - from <= 2u * MAX_TEXEL_PIECES;
  for (uint e = from; e < to && fits; e += 2u) {
    int n = clipPart(c, uvec2(texelPart[e], texelPart[e + 1u]), t, shape);
    fits = n >= 0;
    if (n < 3) continue;
    uint base = (pieces > 0u ? extra + pieces - 1u : k) * SHAPE_STRIDE;
    writePiece(base, n, shape);
    if (pieces > 0u) shooterShape[previous].z = uintBitsToFloat(base);
    previous = base;
    ++pieces;
  }
  if (!fits || pieces == 0u) shooterShape[k * SHAPE_STRIDE] = vec4(0.0);
  else shooterShape[k * SHAPE_STRIDE].y = uintBitsToFloat(pieces);
}
