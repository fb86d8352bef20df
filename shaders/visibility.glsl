// Visibility and form factor of a receiver element from a shooter of the pass. Needs
// hemisphere.glsl, scene.glsl, control.glsl and formfactor.glsl. SAMPLER_ITEM_ID: polygon ids,
// ITEM_FACES layers per shooter, each pixel the nearest surface by exact depth (itembuffer.frag;
// the depths themselves are not read). ItemBuffer::bindForLookup binds all of it.

layout(binding = SAMPLER_ITEM_ID) uniform usampler2DArray itemId;
uniform float farDistance;

#include "segment.glsl"
#ifdef BVH_VISIBILITY
#include "bvh.glsl"
#include "bvh_segment.glsl"
#endif

#ifdef HOST_VISIBILITY
// --visibility bvh traced on the host (src/solver/HostTrace.h): per receiver, in SSBO_RECEIVERS'
// order, HOST_WORDS words, bit s of the pass's radiosity shooter s.
layout(std430, binding = SSBO_HOST_VISIBLE) readonly buffer HostVisible { uint hostVisible[]; };
uint hostReceiver;  // gather.comp's receiver index
float hostVisibility(uint s) { return float((hostVisible[hostReceiver * HOST_WORDS + s / 32u] >> (s % 32u)) & 1u); }
#endif

#ifdef BVH_VISIBILITY
// --visibility bvh (docs/design.md#visibility): every polygon whose BVH boxes the segment meets is
// tested, so no occluder is missed however thin (bvh_segment.glsl's tracedClear).
// A cluster's shooter (src/scene/Clusters.h) is seen from its piece that sends x the most.
float tracedVisibility(uint shooter, vec3 o, vec3 x, vec3 n, uint polygon, float side) {
  uint from = control.shooter[shooter].polygon;
  if (inCluster(from)) clusterEye(control.shooter[shooter].shape, x, n, o, from);
  return tracedClear(o, from, x, polygon, side, SEGMENT_TOLERANCE * farDistance) ? 1.0 : 0.0;
}
#endif

// Point visibility of x (on `polygon`) from the shooter's origin o, robust by construction
// rather than by a depth tolerance: the item buffer only nominates occluders. The 3 x 3 pixels
// around x's projection name the nearest surfaces along nearby rays; each named polygon is then
// tested exactly against the segment o -> x. So a neighbour across a contact or concave corner,
// which fills pixels next to x without crossing the segment, never shadows it, and an emitter
// hung just below a ceiling hides the ceiling behind it however thin the gap, since the test
// uses its plane and outline, not depths. What it can miss: an occluder narrower than a pixel
// that no pixel centre of the window sees.
float visibility(uint shooter, vec3 o, vec3 x, uint polygon) {
  vec3 local = shooterLocal(x, o, control.shooter[shooter].normal.xyz);
  ivec2 size = textureSize(itemId, 0).xy;
  ivec3 centre = itemTexel(local, size) + ivec3(0, 0, int(shooter) * ITEM_FACES);
  float eps = SEGMENT_TOLERANCE * farDistance;
  uint tested = NO_POLYGON;
  // The receiver's own chart does not occlude it: a planar one cannot, and a curved one's element
  // centre (its pieces' centroid) sits off its facets, which would shadow it across a convex fold.
  // (A shooter's chart still does: its facets hide what lies behind a concave block; o lies on
  // the shooter's polygon's plane, scene.glsl's shooterEye, so a convex one's are behind it.)
  uint receiverChart = chartOf(polygon);
  for (int k = 0; k < 9; ++k) {
    ivec3 p = ivec3(clamp(centre.xy + ivec2(k % 3 - 1, k / 3 - 1), ivec2(0), size - 1), centre.z);
    uint q = texelFetch(itemId, p, 0).r;
    if (q == NO_POLYGON || q == polygon || q == tested || chartOf(q) == receiverChart) continue;
    tested = q;
    if (blocksSegment(q, o, x, eps)) return 0.0;
  }
  return 1.0;
}

// Receiver texel t (of `polygon`) lies in the block of shooter s (on the shooter's chart): it
// receives nothing from it.
bool inShooterBlock(uint s, ivec2 t, uint polygon) {
  ivec4 r = control.shooter[s].rect;
  return all(greaterThanEqual(t, r.xy)) && all(lessThan(t, r.xy + r.zw)) && chartOf(polygon) == chartOf(control.shooter[s].polygon);
}

// The same to shooter s of the pass: its node's shape, seen from its origin.
float unoccludedFormFactor(uint s, vec3 x, vec3 nr) {
  vec4 pa = control.shooter[s].positionArea;
  return shapeFormFactor(control.shooter[s].shape, pa.xyz, pa.w, control.shooter[s].normal.xyz, x, nr);
}

// A receiver element of `polygon`: its centre x, normal n and area, fetched from its texel once
// for all the shooters of a pass.
struct Receiver {
  uint polygon;
  vec3 x, n;
  float area;
};

Receiver receiverAt(ivec2 t, uint polygon) {
  vec4 pa = texelFetch(atlasPositionArea, t, 0);
  return Receiver(polygon, pa.xyz, texelFetch(atlasNormal, t, 0).xyz, pa.w);
}

// Form factor from receiver element r to shooter s of the pass, visibility included:
// V(x, o) F(x -> shape_s), x the element's centroid, o the shooter's origin (its item buffer's
// eye). `facing` is false when the pair cannot exchange light (x behind the shooter's plane, or
// the shape behind x's); then the visibility is not looked up and `visible` is 0.
float shooterFormFactor(uint s, Receiver r, out bool facing, out float visible) {
  vec3 origin = control.shooter[s].positionArea.xyz;
  // Cheap, first: half the scene fails it.
  facing = dot(r.x - origin, control.shooter[s].normal.xyz) > -reachBehind(control.shooter[s].polygon);
  float F = facing ? unoccludedFormFactor(s, r.x, r.n) : 0.0;
  facing = F > 0.0;
#if defined(HOST_VISIBILITY)
  visible = facing ? hostVisibility(s) : 0.0;
#elif defined(BVH_VISIBILITY)
  visible = facing ? tracedVisibility(s, origin, r.x, r.n, r.polygon, sqrt(r.area)) : 0.0;
#else
  visible = facing ? visibility(s, origin, r.x, r.polygon) : 0.0;
#endif
  return visible * F;
}
