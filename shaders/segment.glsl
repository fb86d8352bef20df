// Exact segment-polygon occlusion, shared by the gather's visibility (visibility.glsl) and instant
// radiosity's VPL shadows (instant_shade.glsl). Needs scene.glsl (the polygon table and its
// vertices).

// Whether polygon q blocks the segment from o to x: o and x lie strictly on opposite sides of
// its plane (by more than eps, float rounding) and the crossing point lies inside it (convex,
// counter-clockwise around its normal) or within eps of it: two facets sharing an edge each
// round the crossing onto their own plane, and without that margin a segment through the edge
// could miss both (a lamp's segments in a sphere's meridian planes leaked 13 % onto a floor
// texel; tests/BvhVisibilityTest.cpp).
bool blocksSegment(uint q, vec3 o, vec3 x, float eps) {
  vec3 n = polygons[q].normal.xyz;
  float so = dot(n, o) - polygons[q].normal.w, sx = dot(n, x) - polygons[q].normal.w;
  if (!((so > eps && sx < -eps) || (so < -eps && sx > eps))) return false;
  vec3 h = o + (x - o) * (so / (so - sx));
  uvec2 r = polygons[q].vertices.xy;
  for (uint i = 0u; i < r.y; ++i) {
    vec3 a = polygonVertex[r.x + i].xyz, b = polygonVertex[r.x + (i + 1u) % r.y].xyz;
    vec3 e = b - a;
    float d = dot(cross(e, h - a), n);  // |e| x the distance inside the edge's line
    if (d < 0.0 && d * d > eps * eps * dot(e, e)) return false;  // no square root in the walk's hot loop
  }
  return true;
}
