// Scene data on the GPU: the atlas (element centre + area, polygon id per texel) and the
// per-polygon table.

const uint NO_POLYGON = 0xFFFFFFFFu;

struct Polygon {
  vec4 normal;       // xyz unit front normal, w the plane offset n . p
  vec4 reflectance;  // rgb rho; w how far its cluster's parts reach behind its plane (reachBehind)
  vec4 emission;     // rgb E
  uvec4 vertices;    // first, count in polygonVertex (convex, counter-clockwise around the normal);
                     // its chart (src/scene/Charts.h); 1 if that chart is a cluster (Clusters.h)
};

layout(std430, binding = SSBO_POLYGONS) readonly buffer Polygons { Polygon polygons[]; };
layout(std430, binding = SSBO_POLYGON_VERTICES) readonly buffer PolygonVertices { vec4 polygonVertex[]; };

layout(binding = SAMPLER_ATLAS_POSITION_AREA) uniform sampler2D atlasPositionArea;  // xyz element centre, w area (0: none)
layout(binding = SAMPLER_ATLAS_POLYGON) uniform usampler2D atlasPolygon;      // polygon id or NO_POLYGON
layout(binding = SAMPLER_ATLAS_NORMAL) uniform sampler2D atlasNormal;        // xyz the element's receiver normal

// p moved along the normal of polygon's plane onto it.
vec3 ontoPlane(vec3 p, uint polygon) {
  vec4 plane = polygons[polygon].normal;
  return p - (dot(plane.xyz, p) - plane.w) * plane.xyz;
}
// Where a shooter of `polygon` with this centre and area sees from. A curved element's or block's
// centre (the mean of its pieces' centroids) sits off its facets: behind them on a convex surface,
// inside the object, where an item buffer sees only the object's own facets hide everything, so it
// looks out from its polygon's plane; in front of them on a concave one, in the open, where it
// stays (the plane there runs behind the surface's rims). A planar one's centre, on its plane to
// rounding, stays bit for bit.
vec3 shooterEye(vec3 centre, uint polygon, float area) {
  float behind = polygons[polygon].normal.w - dot(polygons[polygon].normal.xyz, centre);
  return behind > 1e-4 * sqrt(area) ? ontoPlane(centre, polygon) : centre;
}
// How far behind the plane of a shooter's polygon a receiver may lie and still face it: 0, but a
// cluster's (src/scene/Clusters.h) parts lie on many planes around the one it shoots from.
float reachBehind(uint polygon) { return polygons[polygon].reflectance.w; }
bool inCluster(uint polygon) { return polygons[polygon].vertices.w != 0u; }
uint chartOf(uint polygon) { return polygon == NO_POLYGON ? NO_POLYGON : polygons[polygon].vertices.z; }
// The chart of atlas texel t, NO_POLYGON outside the atlas: charts touch its border (no gutters,
// src/scene/AtlasPacker.h), and texelFetch out of range is undefined (0 under robust access:
// polygon 0's chart).
uint chartAtTexel(ivec2 t) {
  return all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, textureSize(atlasPolygon, 0))) ? chartOf(texelFetch(atlasPolygon, t, 0).r)
                                                                                             : NO_POLYGON;
}
