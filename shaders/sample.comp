// Stochastic iteration's shooter selection (seed 000 §3.1), on the GPU: shooter k descends the
// luminance sum pyramid from its root, at each level picking a child with probability child /
// (sum of the four) from a fresh counter-based draw, so it ends at texel j with probability
// P_j = lum(B_j) A_j / Phi. It then fills control slot k as a one-texel shooter with
// shot = B_j / (P_j K): the K shots' sum is an unbiased estimate of T B (eq. 3), and its
// shape (the texel's element, its pieces) in SSBO_SHOOTER_SHAPES slot k for the exact form factor.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "control.glsl"
#include "formfactor.glsl"
#include "pyramid.glsl"
#include "random.glsl"
#include "texel_shape.glsl"

layout(local_size_x = 64) in;
layout(binding = IMAGE_RADIOSITY, rgba32f) readonly uniform image2D radiosity;
uniform uint seed, iteration, shooters, topLevel, atlasWidth;

// The leaf texel reached from the root by shooter k's draws.
uvec2 descend(uint k) {
  uvec2 node = uvec2(0u);
  for (uint level = topLevel; level > 0u; --level) {
    float c[4];
    children(level - 1u, node, c);
    float target = uniformDraw(seed, iteration, k, level) * ((c[0] + c[1]) + (c[2] + c[3]));
    uint pick = 4u, last = 0u;
    float running = 0.0;
    for (uint i = 0u; i < 4u; ++i) {
      if (c[i] <= 0.0) continue;
      last = i;
      running += c[i];
      if (pick == 4u && target < running) pick = i;
    }
    if (pick == 4u) pick = last;  // rounding carried the target past the last non-empty child
    node = 2u * node + uvec2(pick & 1u, pick >> 1u);
  }
  return node;
}

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= shooters) return;
  if (k == 0u) control.shots = iteration;
  float phi = pyramid[pyramidOffset(topLevel)];
  ivec2 t = ivec2(descend(k));
  float leaf = pyramid[t.y * pyramidSide + uint(t.x)];
  vec4 pa = texelFetch(atlasPositionArea, t, 0);
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
  bool none = phi <= 0.0 || leaf <= 0.0 || polygon == NO_POLYGON;  // a scene without light
  control.shooter[k].positionArea = none ? pa : vec4(shooterEye(pa.xyz, polygon, pa.w), pa.w);
  // The element's mean normal: a texel of a curved chart spans polygons (a polygon's own otherwise).
  control.shooter[k].normal = vec4(none ? vec3(0.0, 0.0, 1.0) : texelFetch(atlasNormal, t, 0).xyz, 0.0);
  control.shooter[k].shot = none ? vec4(0.0) : vec4(imageLoad(radiosity, t).rgb * (phi / (leaf * float(shooters))), 0.0);
  control.shooter[k].rect = ivec4(t, 1, 1);
  control.shooter[k].polygon = none ? NO_POLYGON : polygon;
  control.shooter[k].power = none ? 0.0 : leaf / phi;  // P_j
  control.shooter[k].block = k;
  control.shooter[k].shape = k;  // its shape: slot k of SSBO_SHOOTER_SHAPES
  if (none) shooterShape[k * SHAPE_STRIDE] = vec4(0.0);
  else writeTexelShape(k, polygon, t, atlasWidth);
}
