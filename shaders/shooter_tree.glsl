// The shooter tree (src/solver/ShooterTree.h): blocks and their quadrants, with static
// geometry, and the unshot statistics node_stats.comp gathers for each node every pass.

const uint NO_CHILD = 0xFFFFFFFFu;

struct Node {
  ivec4 rect;        // atlas x, y, w, h (w = 0: empty)
  vec4 centreArea;   // area-weighted centre of its elements, their area
  uint polygon;
  uint firstChild;   // four consecutive children, or NO_CHILD
  uint firstLeaf;    // blocks only: their 4^depth leaves
  uint depth;        // blocks only
  vec4 normal;       // xyz its shooting normal: its chart's plane, or a curved chart's area-weighted mean;
                     // w its radius: centre to its farthest element's corner
};

struct NodeStats {
  vec4 unshot;       // sum of dB A (rgb) and dI A (a)
  vec4 lightCentre;  // sum of w x, sum of w, w = luminance(dB) A: where its unshot light sits
  vec4 viewCentre;   // the same with w = |dI| A
  vec4 range;        // least and largest luminance(dB) of its elements, largest received importance I - R (alpha of B), 0
};

layout(std430, binding = SSBO_NODES) readonly buffer Nodes { Node nodes[]; };
#ifdef WRITES_NODE_STATS
layout(std430, binding = SSBO_NODE_STATS) writeonly buffer Stats { NodeStats stats[]; };
#else
layout(std430, binding = SSBO_NODE_STATS) readonly buffer Stats { NodeStats stats[]; };
#endif

// The node `depth` levels below root b along `path` (two bits a level, the deepest lowest): walks
// of a tree that call segmentBlocked per node keep their place in a path, not a stack array (a
// stack-array walk lost nodes on llvmpipe: a furnace regathered so gave 1.67 instead of 2, the
// H200 2; likely llvmpipe's loop limit, bvh.glsl, which its extra loop turns passed sooner).
uint nodeOnPath(uint b, uint depth, uint path) {
  uint n = b;
  for (uint l = depth; l > 0u; --l) n = nodes[n].firstChild + ((path >> (2u * (l - 1u))) & 3u);
  return n;
}

// A path walk's two moves, children first to last (last to first with `lastFirst`): into a node's
// first child to visit, and, a node done, on to the next (false when the walk is back at its root).
void pathDown(inout uint depth, inout uint path, bool lastFirst) {
  ++depth;
  path = (path << 2) | (lastFirst ? 3u : 0u);
}
bool pathNext(inout uint depth, inout uint path, bool lastFirst) {
  uint lastChild = lastFirst ? 0u : 3u;
  while (depth > 0u && (path & 3u) == lastChild) --depth, path >>= 2;  // past the last children, up
  if (depth == 0u) return false;
  path = lastFirst ? path - 1u : path + 1u;  // the next sibling
  return true;
}
