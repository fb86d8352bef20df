// One pass, gathered at every receiver texel (seed 003 §39.2): for each shooter of the pass,
// visibility from its item buffer, the exact form factor to its shape (formfactor.glsl), and
// B += rho dB_s F, dB += rho dB_s F (by reciprocity the right quantity for shooting).
// A shooter block's own dB is reset here (its texels are coplanar with it and receive nothing
// from it, but do receive from the pass's other shooters). Importance (alpha: received I - R in
// B, dI in dB) travels the same way from importance shooters, as light's adjoint: reflected by the
// importance shooter's luminance(rho), not the receiver's (shooter_block.glsl; seed 004).
// Perspective-driven solves (seed 004 §5) restrict who receives radiosity: viewMode 1 only
// surfaces in view; viewMode 2 (deferred passes) only surfaces becoming visible, each receiving
// its stored table entry from the pass's blocks instead of their unshot radiosity.
// DIRECT_ONLY (src/solver/DirectSplit.h): receivers keep what they receive in B but not in dB, so
// only the emitters ever shoot and B ends as E + the direct light, element by element.
#include "hemisphere.glsl"
#include "scene.glsl"
#include "control.glsl"
#include "formfactor.glsl"
#include "visibility.glsl"
#ifdef REFINE_NEAR
#include "shooter_tree.glsl"
#ifndef BVH_VISIBILITY  // else visibility.glsl has them
#include "bvh.glsl"
#include "bvh_segment.glsl"
#endif
#include "refine_near.glsl"
#include "transfer_split.glsl"
#endif
#ifdef PERSPECTIVE
#include "perspective.glsl"
uniform uint viewMode;
#endif

#include "linear_group.glsl"

// One invocation a receiver texel, in the order of src/solver/ReceiverOrder.h: x | y << 16.
layout(local_size_x = GATHER_GROUP) in;  // ProgressiveSolver.cpp kGatherGroup
layout(std430, binding = SSBO_RECEIVERS) readonly buffer Receivers { uint receiverTexel[]; };
layout(binding = IMAGE_RADIOSITY, rgba32f) uniform image2D radiosity;
layout(binding = IMAGE_DELTA_B, rgba32f) uniform image2D deltaB;
uniform uint receiverCount;

void main() {
  uint i = linearInvocation(GATHER_GROUP);
  // Once stopped, passes are empty.
  if (control.count + control.importanceCount == 0u || i >= receiverCount) return;
  ivec2 t = ivec2(receiverTexel[i] & 0xFFFFu, receiverTexel[i] >> 16);
#ifdef HOST_VISIBILITY
  hostReceiver = i;
#endif
  uint polygon = texelFetch(atlasPolygon, t, 0).r;
#ifdef PERSPECTIVE
  bool deferred = viewMode == 2u;
  uvec4 view = surfaceView[polygon];
  uint entering = view.y;
  if (deferred && entering == 0u) return;
  bool receivesRadiosity = viewMode == 0u || deferred || view.x != 0u;
#else
  const bool deferred = false, receivesRadiosity = true;
#endif
  Receiver r = receiverAt(t, polygon);
  vec4 received = vec4(0.0);
  vec4 keep = vec4(1.0);  // 0 in the channels this texel's own block shoots this pass
#ifdef REFINE_NEAR
  const bool firstDispatch = splitPhase == 0u && nearSlot == 0u;  // a shooter's own dB is reset once
#else
  const bool firstDispatch = true;
#endif
  for (uint s = 0u; s < control.shootersPerPass + control.importanceCount; ++s) {
    if (!activeShooter(s)) continue;
    vec4 shot = control.shooter[s].shot;
#ifdef PERSPECTIVE
    uint b = control.shooter[s].block;
    if (deferred) shot = vec4(snapshot[(view.z - 1u) * blockCount + b].rgb - snapshot[(entering - 1u) * blockCount + b].rgb, 0.0);
#endif
    if (inShooterBlock(s, t, polygon)) {  // (a deferred pass shoots table entries, not the block's dB)
      if (!deferred && firstDispatch) keep *= s < control.shootersPerPass ? vec4(0.0, 0.0, 0.0, 1.0) : vec4(1.0, 1.0, 1.0, 0.0);
      continue;
    }
    if (s < control.shootersPerPass && !receivesRadiosity) continue;
    bool facing;
    float visible;
#ifdef REFINE_NEAR
    // Near-shooter refinement (transfer_split.glsl): a radiosity shot (not a stored entry's
    // delivery) near its receiver in phase 0, part by part, one shooter a dispatch (nearSlot);
    // every other pair in phase 1.
    bool near = s < control.shootersPerPass && !deferred && nearNode(control.shooter[s].shape, r.x);
    if (near != (splitPhase == 0u) || (near && s != nearSlot)) continue;
    if (near) {
      received.rgb += nearTransfer(s, t, r.x, polygon);
      continue;
    }
    float F = shooterFormFactor(s, r, facing, visible);
    if (s < control.shootersPerPass && !deferred) F *= farScale(s);
#else
    float F = shooterFormFactor(s, r, facing, visible);
#endif
    if (F > 0.0) received += shot * F;
  }
  if (keep == vec4(1.0) && received == vec4(0.0)) return;
  vec3 rho = polygons[polygon].reflectance.rgb;
  vec4 delta = vec4(rho, 1.0) * received;  // importance arrives already reflected (shooter_block.glsl)
  imageStore(radiosity, t, imageLoad(radiosity, t) + delta);
#ifdef DIRECT_ONLY
  delta.rgb = vec3(0.0);  // received light is not handed on (importance, in alpha, still is)
#endif
  imageStore(deltaB, t, imageLoad(deltaB, t) * keep + delta);
}
