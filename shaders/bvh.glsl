// Nearest-hit ray traversal of the scene's BVH (src/solver/Bvh.h, which mirrors this walk on the
// CPU for tests). SSBO_BVH_NODES the nodes, SSBO_BVH_TRIANGLES the triangles; every member a vec4 (seed 002 §4.1).

struct BvhNode {
  vec4 lo;  // xyz box min; w (uint bits): inner node: the index past its subtree; leaf: first triangle
  vec4 hi;  // xyz box max; w (uint bits): leaf: triangle count; inner node: 0
};
struct BvhTriangle {
  vec4 v0;  // w (uint bits): polygon id
  vec4 e1, e2;
};
layout(std430, binding = SSBO_BVH_NODES) readonly buffer BvhNodes { BvhNode bvhNode[]; };
layout(std430, binding = SSBO_BVH_TRIANGLES) readonly buffer BvhTriangles { BvhTriangle bvhTriangle[]; };

const float BVH_MISS = 3.402823e38;

// llvmpipe (Mesa 22.3's gallivm) counts an invocation's loop iterations with one counter for all
// its loops and, past 65,535 (LP_MAX_TGSI_LOOP_ITERATIONS), ends every loop at its next turn: a
// walk cut there answers wrongly and says nothing. Walks that end unfinished set walksCut, which
// the host turns into an error (BvhBuffers::requireWholeWalks; tests/WalkGuardGLTest.cpp).
layout(std430, binding = SSBO_WALKS_CUT) buffer WalksCut { uint walksCut; };
void walkEnded(bool whole) {
  if (!whole) walksCut = 1u;
}

// The walk, in preorder and without a stack (src/solver/Bvh.h): from node n into its first child,
// which follows it, when the walk meets an inner node's box (`enter`); else past its subtree.
// A walk runs `for (uint n = 0u, end = bvhNext(0u, false); n < end; n = bvhNext(n, hit))`.
uint bvhNext(uint n, bool enter) {
  return enter || floatBitsToUint(bvhNode[n].hi.w) != 0u ? n + 1u : floatBitsToUint(bvhNode[n].lo.w);
}

float bvhHitTriangle(uint i, vec3 o, vec3 d) {
  vec3 e1 = bvhTriangle[i].e1.xyz, e2 = bvhTriangle[i].e2.xyz, p = cross(d, e2);
  float det = dot(e1, p);
  if (det == 0.0) return -1.0;
  float inv = 1.0 / det;
  vec3 s = o - bvhTriangle[i].v0.xyz;
  float u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return -1.0;
  vec3 q = cross(s, e1);
  float v = dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return -1.0;
  return dot(e2, q) * inv;
}

bool bvhHitBox(uint n, vec3 o, vec3 invD, float tMax) {
  vec3 t0 = (bvhNode[n].lo.xyz - o) * invD, t1 = (bvhNode[n].hi.xyz - o) * invD;
  vec3 lo = min(t0, t1), hi = max(t0, t1);
  return max(max(lo.x, lo.y), max(lo.z, 0.0)) <= min(min(hi.x, hi.y), min(hi.z, tMax));
}

// The nearest hit t > 0 along o + t d, ignoring polygon `skip`; BVH_MISS if none. `polygon`: the hit's.
float bvhIntersect(vec3 o, vec3 d, uint skip, out uint polygon) {
  vec3 invD = 1.0 / d;
  float tMax = BVH_MISS;
  polygon = 0xFFFFFFFFu;
  bool hit;
  uint n = 0u, end = bvhNext(0u, false);
  for (; n < end; n = bvhNext(n, hit)) {
    hit = bvhHitBox(n, o, invD, tMax);
    uint first = floatBitsToUint(bvhNode[n].lo.w), count = hit ? floatBitsToUint(bvhNode[n].hi.w) : 0u;
    for (uint i = first; i < first + count; ++i) {  // a leaf's triangles
      uint q = floatBitsToUint(bvhTriangle[i].v0.w);
      if (q == skip) continue;
      float t = bvhHitTriangle(i, o, d);
      if (t > 0.0 && t < tMax) tMax = t, polygon = q;
    }
  }
  walkEnded(n >= end);
  return tMax;
}
