// Exact differential-area-to-polygon form factor (Lambert's contour formula), unoccluded. The
// CPU twin is cpu::pointToPolygon (cpu/ExactFormFactor.cpp, double): the same clipped outline
// (stored there, streamed here) and the same atan2 sum.
// Needs hemisphere.glsl (PI). Shapes live in SSBO_SHOOTER_SHAPES, a slot of SHAPE_STRIDE vec4s
// each for their first piece: the vertex count (x), then up to MAX_SHAPE_VERTICES vertices (the shooter tree's nodes, stochastic
// iteration's texels, the tests' probe cases). Both limits: src/solver/ShaderContract.h.

layout(std430, binding = SSBO_SHOOTER_SHAPES) buffer ShooterShapes { vec4 shooterShape[]; };

// F from dA at x (unit normal n) to convex shape `shape` (counter-clockwise around its front
// normal nf); 0 when x lies behind its plane. The shape is clipped to x's front half-space and
//   F = -(1/2pi) sum_i atan2(|c_i|, a_i.b_i) (n.c_i)/|c_i|,  a_i = p_i - x, b_i = p_i+1 - x, c_i = a_i x b_i
// summed over the clipped outline. The outline is streamed, never stored: each edge contributes
// its part in front of the plane, and the cut adds one closing edge from where the outline
// leaves the half-space to where it re-enters (a convex shape crosses the plane at most twice).
// Local arrays would cost a scratch-memory round trip per vertex (llvmpipe: per lane).
// Float care, for polygons far from x or small (subtending angle t): atan2 rather than acos,
// and c_i = a_i x (p_i+1 - p_i) with vertices taken relative to vertex 0, not as b_i - a_i,
// whose cancellation would cost a relative 1e-7 / t in each term and far more in their sum (~t^2).
float contourTerm(vec3 xr, vec3 n, vec3 p, vec3 q) {
  vec3 a = p - xr, e = q - p;
  vec3 k = cross(a, e);
  float s = length(k);
  return s > 0.0 ? atan(s, dot(a, a + e)) * dot(k, n) / s : 0.0;
}

// The clipped outline, streamed: the running sum, the last vertex p (relative to the first, as
// xr is) and its height dp over x's plane, and where the outline left and re-entered it.
struct Contour {
  vec3 xr, n, p, leave, enter;
  float dp, sum;
  bool cut;
};

Contour contourStart(vec3 xr, vec3 n) { return Contour(xr, n, vec3(0.0), vec3(0.0), vec3(0.0), dot(-xr, n), 0.0, false); }

// The edge from the last vertex to q, its part in front of x's plane.
void contourEdge(inout Contour c, vec3 q) {
  float dq = dot(q - c.xr, c.n);
  vec3 h = c.p + (q - c.p) * (c.dp / (c.dp - dq));  // where p -> q crosses the plane, if it does
  if (c.dp >= 0.0 && dq >= 0.0) c.sum += contourTerm(c.xr, c.n, c.p, q);
  else if (c.dp >= 0.0) c.sum += contourTerm(c.xr, c.n, c.p, h), c.leave = h, c.cut = true;
  else if (dq >= 0.0) c.sum += contourTerm(c.xr, c.n, h, q), c.enter = h;
  c.p = q, c.dp = dq;
}

float contourEnd(Contour c) {
  if (c.cut) c.sum += contourTerm(c.xr, c.n, c.leave, c.enter);
  return max(0.0, -c.sum / (2.0 * PI));
}

// F to the piece whose slot starts at `base`.
float pointToPiece(vec3 x, vec3 n, uint base, vec3 nf) {
  int count = int(shooterShape[base].x);
  vec3 v0 = shooterShape[base + 1u].xyz;
  if (count < 3 || dot(x - v0, nf) <= 0.0) return 0.0;
  Contour c = contourStart(x - v0, n);
  for (int i = 1; i <= count; ++i) contourEdge(c, i < count ? shooterShape[base + 1u + uint(i)].xyz - v0 : vec3(0.0));
  return contourEnd(c);
}

// F to the quadrilateral a b c d (counter-clockwise around its front normal nf).
float pointToQuad(vec3 x, vec3 n, vec3 a, vec3 b, vec3 c, vec3 d, vec3 nf) {
  if (dot(x - a, nf) <= 0.0) return 0.0;
  Contour k = contourStart(x - a, n);
  contourEdge(k, b - a), contourEdge(k, c - a), contourEdge(k, d - a), contourEdge(k, vec3(0.0));
  return contourEnd(k);
}

// F to the single convex piece in slot `shape`.
float pointToPolygon(vec3 x, vec3 n, uint shape, vec3 nf) { return pointToPiece(x, n, shape * SHAPE_STRIDE, nf); }

// The front normal of the piece at `base` (Newell's, unnormalised: only its sign is used).
vec3 pieceNormal(uint base) {
  int count = int(shooterShape[base].x);
  vec3 sum = vec3(0.0), v0 = shooterShape[base + 1u].xyz;
  for (int i = 1; i + 1 < count; ++i)
    sum += cross(shooterShape[base + 1u + uint(i)].xyz - v0, shooterShape[base + 2u + uint(i)].xyz - v0);
  return sum;
}

// A cluster's pieces (src/scene/Clusters.h) lie apart, and the nearest decide what x (normal n)
// receives, so its visibility is tested from the piece that sends x the most by the point-to-disc
// estimate A cos cos / r^2: eye and from become that piece's vertex mean and polygon (its header's
// w holds the polygon + 1). A disc shape (no pieces), or pieces that name no polygon (stochastic
// iteration's texel shapes, texel_shape.glsl), keep them.
void clusterEye(uint shape, vec3 x, vec3 n, inout vec3 eye, inout uint from) {
  uint base = shape * SHAPE_STRIDE, pieces = max(floatBitsToUint(shooterShape[base].y), 1u);
  if (shooterShape[base].x < 3.0 || floatBitsToUint(shooterShape[base].w) == 0u) return;
  float best = 0.0;
  for (uint k = 0u, b = base; k < pieces; ++k, b = floatBitsToUint(shooterShape[b].z)) {
    int count = int(shooterShape[b].x);
    vec3 c = vec3(0.0);
    for (int i = 0; i < count; ++i) c += shooterShape[b + 1u + uint(i)].xyz;
    vec3 d = x - c / float(count);
    float r2 = dot(d, d), w = max(dot(pieceNormal(b), d), 0.0) * max(-dot(n, d), 0.0) / (r2 * r2);
    if (w > best) best = w, eye = c / float(count), from = floatBitsToUint(shooterShape[b].w) - 1u;
  }
}

// F to a shape of one or more convex pieces (a block over several polygons of a chart): the
// contour integral is linear in the shape, so the pieces' sum is exact, coplanar or not. The
// first piece's header holds the piece count (y, bits); each header's z the offset (in vec4s,
// bits) of the next piece, which takes only its own vertex count + 1 vec4s (SolverState.h); a
// cluster's piece's w its polygon + 1 (bits, clusterEye).
float pointToShape(vec3 x, vec3 n, uint shape, vec3 nf) {
  uint base = shape * SHAPE_STRIDE, pieces = floatBitsToUint(shooterShape[base].y);
  if (pieces <= 1u) return pointToPiece(x, n, base, nf);
  float sum = 0.0;
  for (uint k = 0u, b = base; k < pieces; ++k, b = floatBitsToUint(shooterShape[b].z))
    sum += pointToPiece(x, n, b, pieceNormal(b));
  return sum;
}

// Unoccluded form factor from the receiver point x (normal nr) to a shooter-tree node's shape
// (front normal ns): exact (the contour integral above), or the disc formula, the disc of its
// area at `centre`, for a shape too complex for the table.
float shapeFormFactor(uint shape, vec3 centre, float area, vec3 ns, vec3 x, vec3 nr) {
  if (shooterShape[shape * SHAPE_STRIDE].x >= 3.0) return pointToShape(x, nr, shape, ns);
  vec3 d = x - centre;
  float r2 = dot(d, d);
  vec3 w = d * inversesqrt(r2);
  return discFormFactor(dot(ns, w), -dot(nr, w), r2, area);
}
