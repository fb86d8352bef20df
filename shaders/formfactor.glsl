// Exact differential-area-to-polygon form factor (Lambert's contour formula), unoccluded. The
// CPU twin is cpu::pointToPolygon (cpu/ExactFormFactor.cpp, double): same clip, same atan2 sum.
// Needs hemisphere.glsl (PI).

const int MAX_SHAPE_VERTICES = 12;  // a convex polygon of <= 8 sides cut by a block's rectangle

// F from dA at x (unit normal n) to the convex polygon v[0..count) (counter-clockwise around its
// front normal nf); 0 when x lies behind its plane. The polygon is first clipped to x's front
// half-space (Sutherland-Hodgman against one plane), then
//   F = -(1/2pi) sum_i atan2(|c_i|, a_i.b_i) (n.c_i)/|c_i|,  a_i = p_i - x, b_i = p_i+1 - x, c_i = a_i x b_i.
// Float care, for polygons far from x or small (subtending angle t): atan2 rather than acos,
// and c_i = a_i x (p_i+1 - p_i) with the edge taken from vertices relative to v[0], not as
// b_i - a_i, whose cancellation would cost a relative 1e-7 / t in each term and far more in
// their sum (~t^2).
float pointToPolygon(vec3 x, vec3 n, vec3 v[MAX_SHAPE_VERTICES], int count, vec3 nf) {
  if (count < 3 || dot(x - v[0], nf) <= 0.0) return 0.0;
  vec3 xr = x - v[0], c[MAX_SHAPE_VERTICES + 1];  // c: the clipped polygon, relative to v[0]
  int m = 0;
  for (int i = 0; i < count; ++i) {
    vec3 p = v[i] - v[0], q = v[(i + 1) % count] - v[0];
    float da = dot(p - xr, n), db = dot(q - xr, n);
    if (da >= 0.0 && m <= MAX_SHAPE_VERTICES) c[m++] = p;
    if ((da >= 0.0) != (db >= 0.0) && m <= MAX_SHAPE_VERTICES) c[m++] = p + (q - p) * (da / (da - db));
  }
  if (m < 3) return 0.0;
  float sum = 0.0;
  for (int i = 0; i < m; ++i) {
    vec3 a = c[i] - xr, e = c[(i + 1) % m] - c[i];
    vec3 k = cross(a, e);
    float s = length(k);
    if (s > 0.0) sum += atan(s, dot(a, a + e)) * dot(k, n) / s;
  }
  return max(0.0, -sum / (2.0 * PI));
}
