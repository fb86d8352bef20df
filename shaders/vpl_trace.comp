// VPL generation (seed 002 §3; Keller 1997): one invocation per light path. Path i starts on an
// emitter (chosen by power, stratified over the paths), leaves it cosine-distributed and
// bounces through the BVH. Keller's quasi-random walk is the Russian roulette: of the n[j-1]
// paths that reached level j - 1 the first n[j] go on (n[j] ~ rhoAvg^j n[0]), the survivors'
// flux scaled by n[j-1] / n[j], so the VPL count is fixed and the estimate unbiased. Each level
// j path writes VPL slot offset[j] + i: the layout, so the result, is independent of scheduling.
layout(local_size_x = 64) in;
#include "hemisphere.glsl"
#include "random.glsl"
#include "scene.glsl"
#include "bvh.glsl"
#include "vpl.glsl"
#include "emitters.glsl"
#include "linear_group.glsl"

struct PathEnd {
  vec4 escaped;  // rgb flux that left the scene; a: 1 if it did
  vec4 behind;   // rgb flux that hit a polygon's back (black) side; a: 1 if it did
};
layout(std430, binding = SSBO_PATH_ENDS) writeonly buffer PathEnds { PathEnd pathEnd[]; };

const int MAX_LEVELS = 16;
uniform uint levelCount[MAX_LEVELS];   // n[j]: paths that reach level j (0 after the last)
uniform uint levelOffset[MAX_LEVELS];  // first VPL slot of level j
uniform uint seed;

vec3 cosineDirection(vec3 n, uint path, uint level) {
  float u1 = uniformDraw(seed, path, level, 2u), u2 = uniformDraw(seed, path, level, 3u);
  float r = sqrt(u1), phi = 2.0 * PI * u2;
  vec3 t, b;
  shooterBasis(n, t, b);
  return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u1)) * n);
}

void main() {
  uint path = linearInvocation(gl_WorkGroupSize.x);
  if (path >= levelCount[0]) return;
  uint e = pickEmitter((float(path) + uniformDraw(seed, path, 0u, 0u)) / float(levelCount[0]));
  float u = uniformDraw(seed, path, 0u, 1u), v = uniformDraw(seed, path, 0u, 4u);
  if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
  vec3 x = emitter[e].v0.xyz + u * emitter[e].e1.xyz + v * emitter[e].e2.xyz;
  uint polygon = floatBitsToUint(emitter[e].e1.w);
  vec3 n = polygons[polygon].normal.xyz;
  vec3 flux = emitter[e].flux.rgb / float(levelCount[0]);
  vpl[levelOffset[0] + path] = Vpl(vec4(x, uintBitsToFloat(polygon)), vec4(n, 0.0), vec4(flux, 0.0));
  pathEnd[path] = PathEnd(vec4(0.0), vec4(0.0));
  for (uint j = 1u; j < uint(MAX_LEVELS) && path < levelCount[j]; ++j) {
    vec3 d = cosineDirection(n, path, j);
    uint hit;
    float t = bvhIntersect(x, d, polygon, hit);
    if (t == BVH_MISS) {
      pathEnd[path].escaped = vec4(flux, 1.0);
      return;
    }
    if (dot(polygons[hit].normal.xyz, d) >= 0.0) {  // its back: hemirad's polygons receive in front only
      pathEnd[path].behind = vec4(flux, 1.0);
      return;
    }
    x += t * d;
    polygon = hit;
    n = polygons[hit].normal.xyz;
    flux *= polygons[hit].reflectance.rgb * (float(levelCount[j - 1u]) / float(levelCount[j]));
    vpl[levelOffset[j] + path] = Vpl(vec4(x, uintBitsToFloat(polygon)), vec4(n, float(j)), vec4(flux, 0.0));
  }
}
