// A shooter seen part by part from near it (issue 30, after Hanrahan, Salzman and Aupperle 1991's
// link refinement). A shot block takes visibility from one origin and shoots its mean unshot
// light: exact enough far away, wrong close by (a box's face beside a floor block sees the block's
// lit and shadowed parts differently; a corner sees the darker parts of the walls' blocks beside
// it most). For a receiver nearer the shot node than refineNear times its side, the node's
// quadrants are visited, descending while the receiver stays near, each with its own unshot light,
// seen from its own light centre with exact visibility (the BVH nominates polygons, blocksSegment
// decides: no item buffer was drawn from these origins); transfer_split.glsl conserves the shot.
// Needs visibility.glsl, shooter_tree.glsl, bvh.glsl and bvh_segment.glsl.
uniform float refineNear;

// x is near node n: within refineNear of its sides (its area's square root) from its centre.
bool nearNode(uint n, vec3 x) {
  vec4 ca = nodes[n].centreArea;
  vec3 d = x - ca.xyz;
  return dot(d, d) < refineNear * refineNear * ca.w;
}

// What receiver x (normal nr, on `polygon`, an element of side `side`) near shot node `root` gets
// from its parts, descending while x stays near: each part's unshot radiosity times its exact form
// factor, `all` of it and the part each part's own light centre sees (`seen`; `seenRgb` per
// channel), visibility tested exactly as --visibility bvh tests it (tracedClear).
struct NearLight {
  vec3 seenRgb;
  float seen, all;
};

NearLight nearLight(uint root, vec3 x, vec3 nr, uint polygon, float side) {
  float eps = SEGMENT_TOLERANCE * farDistance;
  NearLight l = NearLight(vec3(0.0), 0.0, 0.0);
  // Depth first, the last child first (nodeOnPath; the order fixes the sums' bits).
  uint depth = 0u, path = 0u;
  bool whole = false;  // false if llvmpipe's loop limit ends the walk (bvh.glsl)
  while (true) {
    uint n = nodeOnPath(root, depth, path);
    bool empty = nodes[n].rect.z <= 0;
    if (!empty && nodes[n].firstChild != NO_CHILD && nearNode(n, x)) {
      pathDown(depth, path, true);
      continue;
    }
    NodeStats st = stats[n];
    float area = nodes[n].centreArea.w;
    vec3 o = st.lightCentre.xyz / st.lightCentre.w, ns = nodes[n].normal.xyz;
    // No unshot light here, or x behind it.
    if (!empty && st.lightCentre.w > 0.0 && area > 0.0 && dot(x - o, ns) > -reachBehind(nodes[n].polygon)) {
      float F = shapeFormFactor(n, o, area, ns, x, nr), w = luminance(st.unshot.rgb) / area * F;
      l.all += w;
      if (w > 0.0 && tracedClear(o, nodes[n].polygon, x, polygon, side, eps)) l.seen += w, l.seenRgb += st.unshot.rgb / area * F;
    }
    if (!pathNext(depth, path, true)) {
      whole = true;
      break;
    }
  }
  walkEnded(whole);
  return l;
}
