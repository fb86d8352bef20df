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
  for (uint n = 0u, end = bvhNext(0u, false); n < end; n = bvhNext(n, hit)) {
    hit = bvhHitBox(n, o, invD, 1.0);
    uint first = floatBitsToUint(bvhNode[n].lo.w), count = hit ? floatBitsToUint(bvhNode[n].hi.w) : 0u;
    for (uint i = first; i < first + count; ++i) {  // a leaf's triangles
      uint q = floatBitsToUint(bvhTriangle[i].v0.w);
      uint c = chartOf(q);
      if (c != passA && c != passB && blocksSegment(q, o, x, eps)) return true;
    }
  }
  return false;
}
