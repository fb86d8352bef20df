// The element of texel t as a 3D polygon: its polygon clipped to the texel's square in the
// polygon's chart (what Atlas::elementShape computes in double on the CPU). Needs scene.glsl and
// formfactor.glsl (MAX_SHAPE_VERTICES). SSBO_CHARTS: per polygon its chart frame, 4 vec4s: plane
// origin; u axis, w = texel size; v axis; lower-left corner of cell (0, 0) in plane coordinates
// (xy) and the chart's atlas origin (zw).
layout(std430, binding = SSBO_CHARTS) readonly buffer Charts { vec4 chart[]; };

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

// Returns the vertex count (0: the shape does not fit MAX_SHAPE_VERTICES; callers fall back).
int texelShape(uint polygon, ivec2 t, out vec3 shape[CLIP_VERTICES]) {
  uvec2 r = polygons[polygon].vertices.xy;
  if (r.y > uint(MAX_SHAPE_VERTICES)) return 0;
  int n = int(r.y);
  for (int i = 0; i < CLIP_VERTICES; ++i) shape[i] = i < n ? polygonVertex[r.x + uint(i)].xyz : vec3(0.0);
  vec3 o = chart[4u * polygon].xyz, u = chart[4u * polygon + 1u].xyz, v = chart[4u * polygon + 2u].xyz;
  float size = chart[4u * polygon + 1u].w;
  vec4 c = chart[4u * polygon + 3u];
  vec2 lo = c.xy + (vec2(t) - c.zw) * size, hi = lo + size;
  n = clipAxis(shape, n, o, u, lo.x, 1.0);
  n = clipAxis(shape, n, o, u, hi.x, -1.0);
  n = clipAxis(shape, n, o, v, lo.y, 1.0);
  n = clipAxis(shape, n, o, v, hi.y, -1.0);
  return n >= 3 && n <= MAX_SHAPE_VERTICES ? n : 0;
}
