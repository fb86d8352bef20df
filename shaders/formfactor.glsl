// Exact differential-area-to-polygon form factor (Lambert's contour formula), unoccluded. The
// CPU twin is cpu::pointToPolygon (cpu/ExactFormFactor.cpp, double): same clip, same atan2 sum.
// Needs hemisphere.glsl (PI).

const int MAX_SHAPE_VERTICES = 12;  // a convex polygon of <= 8 sides cut by a block's rectangle

// F from dA at x (unit normal n) to the convex polygon v[0..count) (counter-clockwise around its
// front normal nf); 0 when x lies behind its plane. The polygon is first clipped to x's front
// half-space (Sutherland-Hodgman against one plane), then
//   F = -(1/2pi) sum_i atan2(|c_i|, a_i.b_i) (n.c_i)/|c_i|,  a_i = v_i - x, b_i = v_i+1 - x, c_i = a_i x b_i,
// atan2 rather than acos so that far or small polygons keep float precision. Vertices are taken
// relative to x before anything else, so large scene coordinates do not cost precision.
float pointToPolygon(vec3 x, vec3 n, vec3 v[MAX_SHAPE_VERTICES], int count, vec3 nf) {
  if (count < 3 || dot(x - v[0], nf) <= 0.0) return 0.0;
  vec3 c[MAX_SHAPE_VERTICES + 1];
  int m = 0;
  for (int i = 0; i < count; ++i) {
    vec3 a = v[i] - x, b = v[(i + 1) % count] - x;
    float da = dot(a, n), db = dot(b, n);
    if (da >= 0.0 && m <= MAX_SHAPE_VERTICES) c[m++] = a;
    if ((da >= 0.0) != (db >= 0.0) && m <= MAX_SHAPE_VERTICES) c[m++] = a + (b - a) * (da / (da - db));
  }
  if (m < 3) return 0.0;
  float sum = 0.0;
  for (int i = 0; i < m; ++i) {
    vec3 a = normalize(c[i]), b = normalize(c[(i + 1) % m]);
    vec3 k = cross(a, b);
    float s = length(k);
    if (s > 0.0) sum += atan(s, dot(a, b)) * dot(k, n) / s;
  }
  return max(0.0, -sum / (2.0 * PI));
}
