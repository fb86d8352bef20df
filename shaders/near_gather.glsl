// Per-pixel final gather of the near field (issue 31, `--final-gather near`, src/output/NearGather.h,
// docs/design.md#final-gather). Light from elements nearer a point than a few of their sides
// changes across an element faster than a lookup between element centres can follow: beside a
// crease the other wall fills half a point's hemisphere and less of the centres'. So the near
// field is gathered again, at the pixel's point and at the centres of the elements its lookup
// blends, with the lookup's weights, and the pixel gets the difference: near nodes' blend is
// replaced by their exact light at the point, far ones are in neither and cancel. Needs
// scene.glsl, hemisphere.glsl, formfactor.glsl, segment.glsl, bvh.glsl, bvh_segment.glsl,
// direct.glsl (its segmentEps, the gather's tolerance) and shooter_tree.glsl (the nodes; each node's stats[] hold NearGather's source: unshot.rgb the mean
// light its elements send on, lightCentre where it sits; a single element's viewCentre and range
// its half-axes and slopes, leafProfile's).
// The roots (blocks) this draw gathers, [gatherFirst, gatherEnd): all of them, or a share where
// llvmpipe's loop limit cut a walk (bvh.glsl; Renderer::render draws the shares one by one).
uniform uint gatherFirst, gatherEnd;
uniform float gatherReach;    // a node is near within gatherReach x its radius of its centre

// The chart-masked bilinear lookup of camera.frag: up to four texels and their weights (sum 1).
struct Lookup {
  ivec2 texel[4];
  float weight[4];
  int count;
};

bool nearGatherNode(uint n, vec3 x) {
  float reach = gatherReach * nodes[n].normal.w;  // w: the node's radius
  vec3 d = x - nodes[n].centreArea.xyz;
  return dot(d, d) < reach * reach;
}

// Where node n's light leaves: its light centre on its polygon's plane.
vec3 nodeOrigin(uint n) {
  vec4 c = stats[n].lightCentre;
  return ontoPlane(c.w > 0.0 ? c.xyz / c.w : nodes[n].centreArea.xyz, nodes[n].polygon);
}

// A single element's light is linear across its piece where GatherSources gave it a profile (the
// sources' last two vec4s: the piece's half-axes u and v, u x v along its normal, and the relative
// change of its light across each): p receives S F times the mean of S (1 + the change at each
// sub-cell's centre) over k x k sub-cells of the piece, weighted by the share of F each subtends
// from p. Beside a crease the nearest element of the other wall fills much of p's hemisphere, and
// its light falls toward the crease (the wall's top is lit at grazing angles): a constant S would
// overstate it by ~20 % at a fifth of an element from the crease. From within a piece's side of its
// centre, what p sees most is a strip narrower than a quadrant: 8 x 8 sub-cells there, 2 x 2
// elsewhere (the Cornell box on the H200, 256^2, 10k elements: the 1-px corner band +0.680 ->
// +0.572 %, the process 4.12 -> 4.14 s; docs/design.md#final-gather).
const int kProfileCellsNear = 8;

float leafProfile(uint n, vec3 p, vec3 np) {
  vec4 hu = stats[n].viewCentre, hv = stats[n].range;
  if (hu.xyz == vec3(0.0)) return 1.0;
  vec3 c = nodes[n].centreArea.xyz, ns = nodes[n].normal.xyz, d = p - c;
  int k = dot(d, d) < 4.0 * dot(hu.xyz, hu.xyz) ? kProfileCellsNear : 2;
  vec3 u = hu.xyz / float(k), v = hv.xyz / float(k);  // a sub-cell's half-axes
  float sum = 0.0, weights = 0.0;
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      float a = (float(i) + 0.5) / float(k) - 0.5, b = (float(j) + 0.5) / float(k) - 0.5;  // in piece extents
      vec3 qc = c + 2.0 * a * hu.xyz + 2.0 * b * hv.xyz;
      float F = pointToQuad(p, np, qc - u - v, qc + u - v, qc + u + v, qc - u + v, ns);
      sum += F * max(0.0, 1.0 + a * hu.w + b * hv.w), weights += F;
    }
  return weights > 0.0 ? sum / weights : 1.0;
}

// Light node n sends to point p (normal np, on chart `chart`): its mean S (linear across a single
// element where `profile`), exact F from p to its shape, exact visibility from its origin o.
vec3 nodeLight(uint n, vec3 S, vec3 o, vec3 p, vec3 np, uint chart, bool profile) {
  vec3 ns = nodes[n].normal.xyz;
  if (dot(p - o, ns) <= -reachBehind(nodes[n].polygon)) return vec3(0.0);
  float F = shapeFormFactor(n, nodes[n].centreArea.xyz, nodes[n].centreArea.w, ns, p, np);
  if (F <= 0.0 || segmentBlocked(o, p, chart, chartOf(nodes[n].polygon), segmentEps)) return vec3(0.0);
  return S * F * (profile ? leafProfile(n, p, np) : 1.0);
}

// The near field's light at x (normal nx, on `polygon`) minus its blend at the lookup's centres.
// The cut is walked by a path (shooter_tree.glsl's nodeOnPath), not a stack.
vec3 nearCorrection(vec3 x, vec3 nx, uint polygon, Lookup l) {
  uint chart = chartOf(polygon);
  vec3 c[4], nc[4];
  for (int k = 0; k < l.count; ++k)
    c[k] = texelFetch(atlasPositionArea, l.texel[k], 0).xyz, nc[k] = texelFetch(atlasNormal, l.texel[k], 0).xyz;
  vec3 sum = vec3(0.0);
  uint b = gatherFirst;
  for (; b < gatherEnd; ++b) {
    if (!nearGatherNode(b, x)) continue;  // far: the lookup's blend holds it
    uint depth = 0u, path = 0u;
    bool whole = false;  // false if llvmpipe's loop limit ends the walk (bvh.glsl)
    while (true) {
      uint n = nodeOnPath(b, depth, path);
      // An empty quadrant, or a flat part of x's own chart (in x's plane: it sends x nothing).
      bool skip = nodes[n].rect.z <= 0 || (chartOf(nodes[n].polygon) == chart && dot(nodes[n].normal.xyz, nx) > 0.99999);
      if (!skip && nodes[n].firstChild != NO_CHILD && nearGatherNode(n, x)) {
        pathDown(depth, path, false);
        continue;
      }
      vec3 S = stats[n].unshot.rgb, o = nodeOrigin(n);
      // x in the node's plane (a sample on a crease line) gets none of its light, the centres
      // some: no correction rather than one that takes it away.
      skip = skip || S == vec3(0.0) || abs(dot(x - o, nodes[n].normal.xyz)) <= segmentEps;
      if (!skip) {
        // x gets the element's profile; the centres what the solve gave them, a constant S.
        vec3 d = nodeLight(n, S, o, x, nx, chart, true);
        for (int k = 0; k < l.count; ++k) d -= l.weight[k] * nodeLight(n, S, o, c[k], nc[k], chart, false);
        sum += d;
      }
      if (!pathNext(depth, path, false)) {
        whole = true;
        break;
      }
    }
    walkEnded(whole);
  }
  walkEnded(b >= gatherEnd);
  return sum;
}
