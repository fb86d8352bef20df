// The transfer of near-shooter refinement (--refine-near, refine_near.glsl): a receiver near a
// shot block gets each part's own unshot light (a block's parts by a wall or a corner are darker
// than its mean, and a near receiver sees its near parts most), far receivers the block's uniform
// light. What the near ones take less than the uniform light would give them (the deficit) is the
// far field's: the bright parts send more of their light away than the mean says. So the gather
// runs twice: phase 0 the near pairs, which sum the deficit and the uniform light's near share
// atomically; phase 1 the far pairs, scaled by 1 + deficit / (1 - near share), so the shot is
// conserved and, where light leaves the scene (an open side), leaves in the same proportion
// (tests/ShooterTreeTest.cpp). Needs refine_near.glsl and visibility.glsl.
// Phase 0 runs once per radiosity shooter slot of the pass (nearSlot), so that an invocation walks
// one shooter's parts: llvmpipe ends every loop of an invocation once its loops together have run
// 65,535 iterations (bvh.glsl), and one walk per near shooter, 16 in one invocation, passed that
// (Cornell objects 1-4 % dark against element-by-element shooting; docs/design.md).
uniform uint splitPhase;
uniform uint nearSlot;
const float kSplitScale = 16777216.0;  // 2^24: the sums' fixed point, in fractions of the shot power

// Phase 0: what receiver texel t (centre x, on `polygon`) near shooter s gets from its parts; adds
// its deficit and its uniform light to s's sums.
vec3 nearTransfer(uint s, ivec2 t, vec3 x, uint polygon) {
  vec3 nr = texelFetch(atlasNormal, t, 0).xyz;
  float F = unoccludedFormFactor(s, x, nr);
  float shot = luminance(control.shooter[s].shot.rgb), power = shot * control.shooter[s].positionArea.w;
  if (F <= 0.0 || power <= 0.0) return vec3(0.0);
  float area = texelFetch(atlasPositionArea, t, 0).w;
  NearLight l = nearLight(control.shooter[s].shape, x, nr, polygon, sqrt(area));
  // The block's uniform light with the parts' visibility: what x gets without the split.
  float uniformLight = l.all > 0.0 ? shot * F * l.seen / l.all : 0.0;
  float perPower = area / power * kSplitScale;
  atomicAdd(control.nearDeficit[s], int(round((uniformLight - l.seen) * perPower)));
  atomicAdd(control.nearShare[s], int(round(uniformLight * perPower)));
  return l.seenRgb;
}

// Phase 1: the factor on what far receivers get from shooter s (1 without near receivers).
float farScale(uint s) {
  float deficit = float(control.nearDeficit[s]) / kSplitScale, share = float(control.nearShare[s]) / kSplitScale;
  return share < 0.99 ? 1.0 + deficit / (1.0 - share) : 1.0;
}
