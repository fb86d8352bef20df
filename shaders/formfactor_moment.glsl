// Where a point x (unit normal n) receives a planar polygon's light from: the centroid of the
// polygon weighted by the point-to-area kernel K(x, y) = cos_x cos_y / (pi r^2), over the part in
// front of x's plane. A source whose light is linear across it, S (1 + g . (y - c)), sends x
// exactly S F (1 + g . (ybar - c)): near_gather.glsl's leafProfile. Checked against brute-force
// quadrature (tests/HemisphereTest.cpp, formfactor_moment_probe.comp).
// Needs hemisphere.glsl (PI) and formfactor.glsl (Contour: the clipped outline and F).
//
// With o x's foot on the source plane, h its height over it, u = y - o in the plane, beta the
// in-plane part of n and alpha = n . ns, the first moment  V = integral of u K dA  is
//   V = (h / pi) [ integral u (beta . u) / r^4 dA  -  h alpha  integral u / r^4 dA ],  r^2 = h^2 + |u|^2,
// and both area integrals become sums over the outline's edges (divergence theorem, with
// phi = -1 / (2 r^2), grad phi = u / r^4):
//   integral u / r^4 dA = sum_edges nu A1,   A1 = integral phi ds (closed form: atan),
//   integral u (beta . u) / r^4 dA = sum_edges (beta . nu) A2 + (beta / 2) L,
//   A2 = integral u phi ds (closed form: atan, log),  L = integral dA / r^2 = sum_edges e Lambda,
// nu the edge's outward normal and e the edge line's distance from o along it. Lambda is not
// elementary (a dilogarithm); edgeInverseSquare takes it by 6-point Gauss-Legendre after a change
// of variable that makes it smooth (the centroid within 2e-5 of the element's size in the tests).
// Then ybar = o + V / F.

const float GAUSS_X[3] = float[3](0.2386191861, 0.6612093865, 0.9324695142);  // 6-point Gauss-Legendre
const float GAUSS_W[3] = float[3](0.4679139346, 0.3607615730, 0.1713244924);

struct Moment {
  vec3 o, ns, beta;  // x's foot on the plane (relative to the outline's first vertex), the plane's normal
  float h, alpha;
  vec3 a1, a2;       // sum nu A1, sum (beta . nu) A2
  float L;           // integral dA / r^2
};

// e Lambda of one edge: e times the integral over s0..s1 of ln(1 + (e^2 + s^2) / h^2) / (2 (e^2 + s^2)),
// with s = |e| sinh(tau): sign(e) times the integral of ln(1 + e^2 cosh^2(tau) / h^2) / (2 cosh(tau)),
// smooth and decaying however long the edge is against e (in theta = atan(s / e) the integrand has a
// log singularity at +-pi/2, which cost 8-point Gauss 1e-3 of the element's size).
// asinh, odd by construction: NVIDIA's (580) takes log(x + sqrt(x^2 + 1)) as it stands, which
// cancels to nothing for x << -1 (the H100 then made the Cornell box's creases 3 % dark).
float oddAsinh(float x) { return sign(x) * log(abs(x) + sqrt(x * x + 1.0)); }

float edgeInverseSquare(float e, float h, float s0, float s1, float l) {
  if (abs(e) <= 1e-6 * l) return 0.0;  // -> 0 with e
  float t0 = oddAsinh(s0 / abs(e)), t1 = oddAsinh(s1 / abs(e)), mid = 0.5 * (t0 + t1), halfRange = 0.5 * (t1 - t0);
  float sum = 0.0;
  for (int k = 0; k < 3; ++k)
    for (int side = -1; side <= 1; side += 2) {
      float c = cosh(mid + float(side) * halfRange * GAUSS_X[k]);
      sum += GAUSS_W[k] * log(1.0 + e * e * c * c / (h * h)) / (2.0 * c);
    }
  return sign(e) * halfRange * sum;
}

// The edge p -> q of the outline (in the source plane).
void momentEdge(inout Moment m, vec3 p, vec3 q) {
  vec3 d = q - p;
  float l = length(d);
  if (l == 0.0) return;
  vec3 t = d / l, nu = cross(t, m.ns), up = p - m.o;
  float e = dot(up, nu), s0 = dot(up, t), s1 = s0 + l, D2 = m.h * m.h + e * e, D = sqrt(D2);
  float a1 = -(atan(s1 / D) - atan(s0 / D)) / (2.0 * D);
  vec3 a2 = e * a1 * nu - 0.25 * log((D2 + s1 * s1) / (D2 + s0 * s0)) * t;
  m.a1 += a1 * nu, m.a2 += dot(m.beta, nu) * a2;
  m.L += edgeInverseSquare(e, m.h, s0, s1, l);
}

// F from x to the quadrilateral a b c d (counter-clockwise around its unit front normal ns), 0 when
// x is behind it, and its kernel-weighted centroid `ybar` (valid where F > 0).
float kernelCentroid(vec3 x, vec3 n, vec3 a, vec3 b, vec3 c, vec3 d, vec3 ns, out vec3 ybar) {
  ybar = a;
  vec3 xr = x - a;
  float h = dot(xr, ns);
  if (h <= 0.0) return 0.0;
  float alpha = dot(n, ns);
  Moment m = Moment(xr - h * ns, ns, n - alpha * ns, h, alpha, vec3(0.0), vec3(0.0), 0.0);
  // The outline clipped to x's front half-space, streamed as formfactor.glsl's Contour does.
  Contour k = contourStart(xr, n);
  vec3 corner[4] = vec3[4](b - a, c - a, d - a, vec3(0.0));
  for (int i = 0; i < 4; ++i) {
    vec3 p = k.p, q = corner[i];
    float dp = k.dp, dq = dot(q - xr, n);
    vec3 w = p + (q - p) * (dp / (dp - dq));  // where p -> q crosses x's plane, if it does
    if (dp >= 0.0 && dq >= 0.0) momentEdge(m, p, q);
    else if (dp >= 0.0) momentEdge(m, p, w);
    else if (dq >= 0.0) momentEdge(m, w, q);
    contourEdge(k, q);
  }
  if (k.cut) momentEdge(m, k.leave, k.enter);
  float F = contourEnd(k);
  if (F <= 0.0) return 0.0;
  vec3 V = (h / PI) * (m.a2 + 0.5 * m.L * m.beta - h * alpha * m.a1);
  ybar = a + m.o + V / F;
  return F;
}
