// Visibility refined near a shooter (issue 30, after Hanrahan, Salzman and Aupperle 1991's link
// refinement). A shot block takes visibility from one origin: exact enough far away, wrong close
// by (a box's face beside a floor block sees the block's lit and shadowed parts differently). For
// a receiver nearer the shot node than refineNear times its side, the node's quadrants are visited,
// descending while the receiver stays near, each seen from its own light centre with exact
// visibility (the BVH nominates polygons, blocksSegment decides: no item buffer was drawn from
// these origins). Needs visibility.glsl, shooter_tree.glsl, bvh.glsl and bvh_segment.glsl.
uniform float refineNear;

// x is near node n: within refineNear of its sides (its area's square root) from its centre.
bool nearNode(uint n, vec3 x) {
  vec4 ca = nodes[n].centreArea;
  vec3 d = x - ca.xyz;
  return dot(d, d) < refineNear * refineNear * ca.w;
}

// The part of shot node `root` that receiver x (normal nr, on `polygon`) sees, for x near it:
// each part's share of the root's light at x (its unshot radiosity times its exact form factor,
// descending while x stays near) that its origin sees. The transfer itself stays the root's
// (uniform over the root, as for receivers far away): weighting the receivers near a block by its
// parts' light, while those far away get the block's mean, would not conserve what the block
// shoots (the near ones see its near parts, and a block's parts by a wall or a corner are darker:
// 0.35 % of the light of an empty Cornell box lost at 2,508 elements). So this refines visibility
// only, what one origin gets wrong close by.
float visibleShare(uint root, vec3 x, vec3 nr, uint polygon) {
  uint stack[1 + 3 * MAX_SPLIT_DEPTH];  // each level leaves at most three siblings waiting
  int top = 0;
  stack[top++] = root;
  uint chart = chartOf(polygon);
  float eps = 4e-7 * farDistance, seen = 0.0, all = 0.0;
  while (top > 0) {
    uint n = stack[--top];
    if (nodes[n].firstChild != NO_CHILD && nearNode(n, x)) {
      for (uint c = nodes[n].firstChild; c < nodes[n].firstChild + 4u; ++c)
        if (nodes[c].rect.z > 0) stack[top++] = c;
      continue;
    }
    NodeStats st = stats[n];
    float area = nodes[n].centreArea.w;
    if (st.lightCentre.w <= 0.0 || area <= 0.0) continue;  // no unshot light here
    vec3 o = st.lightCentre.xyz / st.lightCentre.w, ns = nodes[n].normal.xyz;
    if (dot(x - o, ns) <= 0.0) continue;
    float w = luminance(st.unshot.rgb) / area * shapeFormFactor(n, o, area, ns, x, nr);
    all += w;
    if (w > 0.0 && !segmentBlocked(o, x, chart, eps)) seen += w;
  }
  return all > 0.0 ? seen / all : 0.0;
}
