// Direct light at a camera pixel's surface point, exactly (issue 31, `--direct per-pixel`,
// docs/design.md#per-pixel-direct): per emitter piece, Lambert's contour integral from the point
// (formfactor.glsl, the gather's kernel) times the share of the piece the point sees. Needs
// hemisphere.glsl, scene.glsl, formfactor.glsl, segment.glsl, bvh.glsl and bvh_segment.glsl.
// The pieces (src/output/DirectLight.h) sit in SSBO_SHOOTER_SHAPES, a slot each: the emitters'
// polygons cut into fans of 3 or 4 vertices, each header's w its polygon id (uint bits).
uniform uint emitterBase;   // the first piece's slot (after the final gather's nodes, NearGather.h)
// The strips this draw adds, [stripFirst, stripEnd), strip piece * G + row: all of them, or a share
// where llvmpipe's loop limit cut a pixel's walks to all (src/output/DirectShares.h).
uniform uint stripFirst, stripEnd;
uniform int directGrid;     // G: visibility is sampled at G x G points a piece
uniform float segmentEps;   // blocksSegment's plane tolerance, as the gather's (SEGMENT_TOLERANCE x far distance)
// pieceMayBeBlocked's loop turns before it answers "may be": a cap on llvmpipe, where its walk over a
// furnished room's clutter alone can pass the loop limit (src/output/DirectLight.h); none on GPUs.
uniform uint pyramidTurns;

// The point (u, v) of a piece as the bilinear patch p0 p1 p2 p3 (a triangle: p3 = p2) and the
// patch's area element |dp/du x dp/dv| there: a triangle's cells near p2 are small, and weigh less.
vec3 piecePoint(uint base, vec2 uv, out float areaElement) {
  int count = int(shooterShape[base].x);
  vec3 p0 = shooterShape[base + 1u].xyz, p1 = shooterShape[base + 2u].xyz, p2 = shooterShape[base + 3u].xyz;
  vec3 p3 = count == 4 ? shooterShape[base + 4u].xyz : p2;
  vec3 du = mix(p1 - p0, p2 - p3, uv.y), dv = mix(p3 - p0, p2 - p1, uv.x);
  areaElement = length(cross(du, dv));
  return mix(mix(p0, p1, uv.x), mix(p3, p2, uv.x), uv.y);
}

// The share of the piece's light that x sees through rows [rows.x, rows.y) of its G x G cell
// centres, each weighted by the point-to-point kernel cos_x cos_y / r^2 dA, each tested exactly
// (the BVH nominates occluders, blocksSegment decides) where `test`, else seen. All rows
// untested: 1, unoccluded light is the contour integral's.
float visibleShare(vec3 x, vec3 n, uint base, vec3 nl, ivec2 rows, bool test) {
  float seen = 0.0, all = 0.0, cell = 1.0 / float(directGrid);
  for (int j = 0; j < directGrid; ++j)
    for (int i = 0; i < directGrid; ++i) {
      float dA;
      vec3 y = piecePoint(base, (vec2(i, j) + 0.5) * cell, dA), d = y - x;
      float r2 = dot(d, d), w = dA * max(dot(n, d), 0.0) * max(-dot(nl, d), 0.0) / (r2 * r2);
      if (w <= 0.0) continue;
      all += w;
      if (j >= rows.x && j < rows.y && (!test || !segmentBlocked(x, y, NO_POLYGON, NO_POLYGON, segmentEps))) seen += w;
    }
  return all > 0.0 ? seen / all : float(rows.y - rows.x) / float(directGrid);  // at the horizon F is ~0 anyway
}

// Whether any triangle of the scene may cross the pyramid from x to the piece (apex x; x in
// front of the piece): the BVH nominates triangles whose boxes meet the pyramid's box, and one is
// dropped when a plane of the pyramid has all its vertices outside (a side face, the piece's
// plane, or x's own plane when the whole piece lies above x's horizon). false: every segment from
// x to the piece is unblocked, and the grid's segment tests would all find so. Past pyramidTurns
// it answers true: the exact tests that follow decide.
bool pieceMayBeBlocked(vec3 x, vec3 n, uint base) {
  int count = int(shooterShape[base].x);
  vec3 p[4], lo = x, hi = x, centre = vec3(0.0);
  for (int i = 0; i < count; ++i) {
    p[i] = shooterShape[base + 1u + uint(i)].xyz;
    lo = min(lo, p[i]), hi = max(hi, p[i]), centre += p[i] / float(count);
  }
  vec3 nl = normalize(cross(p[1] - p[0], p[2] - p[0])), side[4];  // the pyramid's planes, outward
  for (int i = 0; i < count; ++i) {
    side[i] = normalize(cross(p[i] - x, p[(i + 1) % count] - x));
    side[i] *= dot(side[i], centre - x) > 0.0 ? -1.0 : 1.0;
  }
  // A triangle that only touches the pyramid's boundary (a wall meeting the lamp at its edge, x's
  // own plane) blocks no segment inside it: within `touch` of a plane counts as outside, so
  // rounding does not send such points to the grid's 64 segment tests.
  float touch = 1e-5 * length(hi - lo);
  bool aboveHorizon = true;
  for (int i = 0; i < count; ++i) aboveHorizon = aboveHorizon && dot(n, p[i] - x) > 0.0;
  bool hit;
  uint k = 0u, end = bvhNext(0u, false), turns = 0u;
  for (; k < end; k = bvhNext(k, hit)) {
    hit = all(lessThanEqual(bvhNode[k].lo.xyz, hi)) && all(greaterThanEqual(bvhNode[k].hi.xyz, lo));
    uint first = floatBitsToUint(bvhNode[k].lo.w), tris = hit ? floatBitsToUint(bvhNode[k].hi.w) : 0u;
    turns += 1u + tris * uint(count + 1);
    if (turns > pyramidTurns) return true;
    for (uint t = first; t < first + tris; ++t) {
      vec3 a = bvhTriangle[t].v0.xyz, b = a + bvhTriangle[t].e1.xyz, c = a + bvhTriangle[t].e2.xyz;
      bool outside = max(max(dot(nl, a - p[0]), dot(nl, b - p[0])), dot(nl, c - p[0])) <= touch ||
                     (aboveHorizon && max(max(dot(n, a - x), dot(n, b - x)), dot(n, c - x)) <= touch);
      for (int i = 0; i < count && !outside; ++i)
        outside = min(min(dot(side[i], a - x), dot(side[i], b - x)), dot(side[i], c - x)) >= -touch;
      if (!outside) return true;
    }
  }
  walkEnded(k >= end);
  return false;
}

// Whether one polygon hides the whole piece from x: it blocks the segments to every corner. Exact:
// the cone from x over a convex polygon is convex, so it holds the corners' convex hull, the
// piece, beyond the polygon; then every grid segment is blocked too, and none needs testing.
bool pieceHidden(vec3 x, uint base) {
  int count = int(shooterShape[base].x);
  vec3 p0 = shooterShape[base + 1u].xyz, d = p0 - x;
  vec3 invD = 1.0 / mix(d, vec3(1e-30), equal(d, vec3(0.0)));
  bool hit;
  uint k = 0u, end = bvhNext(0u, false);
  for (; k < end; k = bvhNext(k, hit)) {
    hit = bvhHitBox(k, x, invD, 1.0);
    uint first = floatBitsToUint(bvhNode[k].lo.w), tris = hit ? floatBitsToUint(bvhNode[k].hi.w) : 0u;
    for (uint t = first; t < first + tris; ++t) {
      uint q = floatBitsToUint(bvhTriangle[t].v0.w);
      bool all = blocksSegment(q, x, p0, segmentEps);
      for (int i = 1; i < count && all; ++i) all = blocksSegment(q, x, shooterShape[base + 1u + uint(i)].xyz, segmentEps);
      if (all) return true;
    }
  }
  walkEnded(k >= end);
  return false;
}

// rho times the irradiance / pi from this draw's strips of the emitter pieces at point x of
// `polygon`, normal n (its plane's, or a curved chart's smooth normal): the direct part of B there.
// One-sided emitters: a piece lights only points in front of it.
vec3 directLight(vec3 x, vec3 n, uint polygon) {
  x = ontoPlane(x, polygon);  // interpolation leaves ~1e-7
  vec3 sum = vec3(0.0);
  uint grid = uint(directGrid);
  for (uint e = stripFirst / grid; e * grid < stripEnd; ++e) {
    uint base = (emitterBase + e) * uint(SHAPE_STRIDE), lamp = floatBitsToUint(shooterShape[base].w);
    if (lamp == polygon) continue;
    vec3 nl = polygons[lamp].normal.xyz;
    float F = pointToPiece(x, n, base, nl);
    if (F <= 0.0) continue;
    ivec2 rows = ivec2(max(stripFirst, e * grid) - e * grid, min(stripEnd, (e + 1u) * grid) - e * grid);
    bool whole = rows == ivec2(0, directGrid);
    // Most points see a piece whole or not at all: two exact tests spare them the grid's segments.
    float V = !pieceMayBeBlocked(x, n, base) ? (whole ? 1.0 : visibleShare(x, n, base, nl, rows, false))
              : pieceHidden(x, base)          ? 0.0
                                              : visibleShare(x, n, base, nl, rows, true);
    sum += polygons[lamp].emission.rgb * (F * V);
  }
  return polygons[polygon].reflectance.rgb * sum;
}
