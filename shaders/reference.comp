// The unbiased reference (issue 31, docs/reference.md): a path tracer of the solver's own
// model. One invocation per pixel adds `samples` paths of one batch to that pixel's batch sum,
// so every sum is added in one fixed order (deterministic per seed on any backend's schedule).
// A pixel holds B of the surface it sees, as the radiosity renders do: B = E + rho H with the
// irradiance H = integral of B/pi cos over the hemisphere. At each vertex the direct part of H
// comes from one emitter sample picked by power and from the cosine-distributed bounce, the two
// weighed by multiple importance sampling; the bounce's hit then adds its reflected light.
// Emitters emit from their
// front only and back faces are black (hemirad's polygons emit and receive in front only);
// Russian roulette on max(rho), the survivors' weight divided by the survival probability, ends
// the paths unbiased.
layout(local_size_x = 64) in;
#include "hemisphere.glsl"
#include "random.glsl"
#include "scene.glsl"
#include "bvh.glsl"
#include "emitters.glsl"
#include "linear_group.glsl"

layout(std430, binding = SSBO_REFERENCE_SUMS) buffer Sums { vec4 sums[]; };  // per pixel, this batch's

uniform uint width, height, seed;
uniform float totalPower;  // W: the emitters' total lum(E) A
uniform uint firstSample;  // the global index of this dispatch's first sample (batches are runs of indices)
uniform uint samples;      // paths per pixel this dispatch
uniform uint bounces;      // reflections a path may take (--bounces; 1: direct light only), at most MAX_BOUNCES
uniform vec3 eye, corner, dx, dy;  // Camera::pixelRays: window point w looks along corner + w.x dx + w.y dy

const uint MAX_BOUNCES = 4096u;        // a cap roulette reaches with probability < 0.99^4096 ~ 1e-18
const float MAX_SURVIVAL = 0.99;       // so even rho = 1 paths end

const uint DRAWS = 8u;  // draws per bounce: 0-1 direction, 2 roulette, 3 emitter, 4-5 point on it

// Draw k of sample `s` at bounce `depth`: a key of its own for every (pixel, sample, bounce, k).
float draw(uint pixel, uint s, uint depth, uint k) { return uniformDraw(seed, pixel, s, depth * DRAWS + k); }

vec3 cosineDirection(vec3 n, uint pixel, uint s, uint depth) {
  float u1 = draw(pixel, s, depth, 0u), u2 = draw(pixel, s, depth, 1u);
  float r = sqrt(u1), phi = 2.0 * PI * u2;
  vec3 t, b;
  shooterBasis(n, t, b);
  return normalize(r * cos(phi) * t + r * sin(phi) * b + sqrt(max(0.0, 1.0 - u1)) * n);
}

// The solid-angle density with which the emitter samples pick a direction from x to the point y of
// emitter polygon `lamp` at squared distance r2, seen at cos_y: p_A(y) r^2 / cos_y, with the
// power-proportional area density p_A(y) = lum(E_y) / W.
float lampDensity(uint lamp, float r2, float cosY) {
  return dot(polygons[lamp].emission.rgb, LUMINANCE) / totalPower * r2 / cosY;
}

// Multiple importance sampling (Veach's balance heuristic) of the direct light: the emitter
// sample's weight p_lamp / (p_lamp + p_cos), the cosine bounce's p_cos / (p_lamp + p_cos). Either
// technique alone has unbounded variance somewhere (the bounce at a small lamp, the lamp sample
// near a corner of an emitting box); together each covers the other's tail.
float balance(float mine, float other) { return mine / (mine + other); }

// One emitter sample's share of the direct light at x (polygon `self`, normal n): E_y / pi
// cos_x cos_y / (r^2 p_A(y)) times its balance weight.
vec3 directLight(vec3 x, vec3 n, uint self, uint pixel, uint s, uint depth) {
  uint e = pickEmitter(draw(pixel, s, depth, 3u));
  float u = draw(pixel, s, depth, 4u), v = draw(pixel, s, depth, 5u);
  if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
  vec3 y = emitter[e].v0.xyz + u * emitter[e].e1.xyz + v * emitter[e].e2.xyz;
  uint lamp = floatBitsToUint(emitter[e].e1.w);
  vec3 toY = y - x;
  float r2 = dot(toY, toY);
  vec3 d = toY * inversesqrt(r2);
  float cosX = dot(n, d), cosY = -dot(polygons[lamp].normal.xyz, d);
  if (cosX <= 0.0 || cosY <= 0.0 || lamp == self) return vec3(0.0);
  uint hit;
  bvhIntersect(x, d, self, hit);
  if (hit != lamp) return vec3(0.0);  // the nearest polygon along d is the lamp's: y is seen
  float w = balance(lampDensity(lamp, r2, cosY), cosX / PI);
  return emitter[e].flux.rgb * (w * cosX * cosY / (PI * r2));  // flux = E_y / p_A(y)
}

vec3 tracePath(vec3 x, vec3 d, uint pixel, uint s) {
  uint hit;
  float t = bvhIntersect(x, d, NO_POLYGON, hit);
  if (t == BVH_MISS || dot(polygons[hit].normal.xyz, d) >= 0.0) return vec3(0.0);  // nothing, or a back face
  vec3 value = polygons[hit].emission.rgb, weight = vec3(1.0);
  for (uint depth = 0u; depth < min(bounces, MAX_BOUNCES); ++depth) {  // depth + 1 reflections
    x += t * d;
    vec3 n = polygons[hit].normal.xyz, rho = polygons[hit].reflectance.rgb;
    float survive = min(max(rho.r, max(rho.g, rho.b)), MAX_SURVIVAL);
    if (survive <= 0.0) break;
    weight *= rho;
    value += weight * directLight(x, n, hit, pixel, s, depth);
    if (draw(pixel, s, depth, 2u) >= survive) break;
    weight /= survive;
    d = cosineDirection(n, pixel, s, depth);
    uint self = hit;  // a planar polygon cannot occlude itself: no offset epsilon
    t = bvhIntersect(x, d, self, hit);
    float cosY = -dot(polygons[hit].normal.xyz, d);
    if (t == BVH_MISS || cosY <= 0.0) break;  // nothing, or a back face: black
    vec3 E = polygons[hit].emission.rgb;
    if (E != vec3(0.0)) value += weight * E * balance(dot(n, d) / PI, lampDensity(hit, t * t, cosY));
  }
  return value;
}

void main() {
  uint pixel = linearInvocation(gl_WorkGroupSize.x);
  if (pixel >= width * height) return;
  // Image rows go top-down, window rows bottom-up (as GL's and Camera::pixelRays').
  vec2 base = vec2(float(pixel % width), float(height - 1u - pixel / width));
  vec3 sum = vec3(0.0);
  for (uint i = 0u; i < samples; ++i) {
    uint s = firstSample + i;
    vec2 w = base + vec2(draw(pixel, s, MAX_BOUNCES, 0u), draw(pixel, s, MAX_BOUNCES, 1u));  // a box filter
    sum += tracePath(eye, normalize(corner + w.x * dx + w.y * dy), pixel, s);
  }
  sums[pixel] += vec4(sum, 0.0);
}
