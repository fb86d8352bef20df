// Per pass, the unshot statistics of every shooter-tree node (shooter_tree.glsl): one
// workgroup per block of SSBO_BLOCK_LIST (the blocks of one workgroup size, ShooterTree.h statsThreads), its threads split evenly over the block's leaves (each strides over
// its leaf's texels), a fixed-order tree sum per leaf, then the leaves fold into their parents
// level by level. The ranking then reads one entry per block, and the descent one per node, instead
// of walking texels in one invocation per shooter. BLOCK_THREADS: at least one per leaf.
#define WRITES_NODE_STATS
#include "hemisphere.glsl"
#include "scene.glsl"
#include "shooter_tree.glsl"
#include "linear_group.glsl"

layout(local_size_x = BLOCK_THREADS) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) uniform readonly image2D radiosity;  // a: received importance I - R
layout(binding = IMAGE_DELTA_B, rgba32f) uniform readonly image2D deltaB;     // a: unshot importance dI

layout(std430, binding = SSBO_BLOCK_LIST) readonly buffer BlockList { uint blockList[]; };
uniform uint blockCount;  // in the list

const float NONE = 3.4e38;
const uint THREADS = uint(BLOCK_THREADS);
shared NodeStats partial[BLOCK_THREADS];

NodeStats emptyStats() { return NodeStats(vec4(0.0), vec4(0.0), vec4(0.0), vec4(NONE, 0.0, 0.0, 0.0)); }

NodeStats merge(NodeStats a, NodeStats b) {
  return NodeStats(a.unshot + b.unshot, a.lightCentre + b.lightCentre, a.viewCentre + b.viewCentre,
                   vec4(min(a.range.x, b.range.x), max(a.range.y, b.range.y), max(a.range.z, b.range.z), 0.0));
}

// What thread `sub` of `threads` gathers from the leaf's texels.
NodeStats leafPart(ivec4 r, uint sub, uint threads) {
  NodeStats s = emptyStats();
  for (uint k = sub; k < uint(r.z * r.w); k += threads) {
    ivec2 t = r.xy + ivec2(int(k) % r.z, int(k) / r.z);
    vec4 pa = texelFetch(atlasPositionArea, t, 0);
    if (pa.w <= 0.0) continue;
    vec4 d = imageLoad(deltaB, t);
    float lum = luminance(d.rgb), light = lum * pa.w;
    s.unshot += d * pa.w;
    s.lightCentre += vec4(pa.xyz * light, light);
    s.range.xy = vec2(min(s.range.x, lum), max(s.range.y, lum));
#ifdef IMPORTANCE_DRIVEN  // only importance-driven solves rank by importance or shoot it
    float view = abs(d.a) * pa.w;
    s.viewCentre += vec4(pa.xyz * view, view);
    // The key's importance is what the element's light is worth where it lands: I - R, not R
    // (light on a visible element is shown already; seed 004 ranked by I, which sends the shots
    // to whatever is nearest the camera).
    s.range.z = max(s.range.z, imageLoad(radiosity, t).a);
#endif
  }
  return s;
}

// The merge of the four stats starting at partial[first], `step` apart.
NodeStats four(uint first, uint step) {
  return merge(merge(partial[first], partial[first + step]), merge(partial[first + 2u * step], partial[first + 3u * step]));
}

// The first node of level d of the block's tree (0: the block; breadth-first, levels contiguous).
uint levelStart(uint block, uint d) {
  uint n = block;
  for (uint k = 0u; k < d; ++k) n = nodes[n].firstChild;
  return n;
}

void main() {
  uint group = linearGroup(), l = gl_LocalInvocationID.x;
  if (group >= blockCount) return;  // past the count in the tiled grid: the whole group leaves
  uint block = blockList[group];
  uint depth = nodes[block].depth, leaves = 1u << (2u * depth), threads = THREADS / leaves;
  uint leaf = l / threads, sub = l % threads;
  partial[l] = leafPart(nodes[nodes[block].firstLeaf + leaf].rect, sub, threads);
  memoryBarrierShared();
  barrier();
  for (uint stride = threads / 2u; stride > 0u; stride >>= 1) {
    if (sub < stride) partial[l] = merge(partial[l], partial[l + stride]);
    memoryBarrierShared();
    barrier();
  }
  if (sub == 0u) stats[nodes[block].firstLeaf + leaf] = partial[l];
  barrier();  // every leaf is stored before its slot is reused
  // Level by level up from the leaves, a thread a node: node j of level d folds the four
  // children whose sums sit `step` slots apart from slot 4 j step, and leaves its own in the
  // first of them (the slots of different nodes are disjoint).
  for (int d = int(depth) - 1; d >= 0; --d) {
    uint step = threads << (2u * (depth - 1u - uint(d)));
    if (l < (1u << (2u * uint(d)))) {
      partial[4u * l * step] = four(4u * l * step, step);
      stats[levelStart(block, uint(d)) + l] = partial[4u * l * step];
    }
    memoryBarrierShared();
    barrier();
  }
}
