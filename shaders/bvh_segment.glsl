// Exact segment visibility through the scene's BVH: the BVH nominates the polygons whose
// triangles' boxes the segment crosses, blocksSegment (segment.glsl) decides. Shared by the
// near-shooter refinement (refine_near.glsl) and per-pixel direct light (direct.glsl). Needs
// scene.glsl, segment.glsl and bvh.glsl.

// Whether any polygon but those of charts `passA` and `passB` blocks the segment o -> x
// (NO_POLYGON for either: no chart passes).
bool segmentBlocked(vec3 o, vec3 x, uint passA, uint passB, float eps) {
  vec3 d = x - o;
  vec3 invD = 1.0 / mix(d, vec3(1e-30), equal(d, vec3(0.0)));  // an axis-parallel segment: no 0 * inf
  bool hit;
  uint n = 0u, end = bvhNext(0u, false);
  for (; n < end; n = bvhNext(n, hit)) {
    hit = bvhHitBox(n, o, invD, 1.0);
    uint first = floatBitsToUint(bvhNode[n].lo.w), count = hit ? floatBitsToUint(bvhNode[n].hi.w) : 0u;
    for (uint i = first; i < first + count; ++i) {  // a leaf's triangles
      uint q = floatBitsToUint(bvhTriangle[i].v0.w);
      uint c = chartOf(q);
      if (c != passA && c != passB && blocksSegment(q, o, x, eps)) return true;
    }
  }
  walkEnded(n >= end);
  return false;
}

// Whether light travels from o, a point of shooter polygon `from`, to x, the centre of a receiver
// element of `to` (side `side`): --visibility bvh's test and near-shooter refinement's. The
// segment runs where light leaves and arrives: each end onto its polygon's plane (a curved
// chart's centroids sit off its facets), the shooter's and the receiver's charts pass (point
// visibility cannot resolve a surface against itself), and on a curved receiver (its centre off
// its polygon's plane) the last half element side is not tested: the centre stands for a bent
// patch, whose neighbouring facets lie that near. A planar receiver is tested to its centre, so
// contact shadows stay whole. Needs scene.glsl's ontoPlane and chartOf.
bool tracedClear(vec3 o, uint from, vec3 x, uint to, float side, float eps) {
  vec3 a = ontoPlane(o, from), b = ontoPlane(x, to);
  float reach = length(x - b) > 1e-3 * side ? 0.5 * side : 0.0;
  float keep = max(0.0, 1.0 - reach / max(length(b - a), 1e-30));
  return !segmentBlocked(a, a + (b - a) * keep, chartOf(to), chartOf(from), eps);
}
