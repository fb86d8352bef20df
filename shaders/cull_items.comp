// Which chunks of the item mesh each item-buffer layer (shooter, hemicube face) can see: a chunk
// is drawn into a layer unless its bounding box lies wholly below the shooter's horizon or, on a
// hemicube face, wholly outside one side of the face's frustum. Every such bound is linear in the
// point, so a box is outside when its eight corners are; a slack of 1e-4 far keeps float rounding
// conservative. Commands keep the mesh's order within a layer (layer-major), so each layer holds
// exactly what one draw of the whole mesh gives it (ItemBuffer::render). An idle layer draws nothing.
#include "hemisphere.glsl"
#include "control.glsl"

layout(local_size_x = 64) in;
struct DrawCommand {
  uint count, instanceCount, firstIndex;
  int baseVertex;
  uint baseInstance;  // the layer: itembuffer.vert's per-instance attribute
};
// Per chunk: bounds min (xyz) and its first index (w, bits); bounds max and its index count.
layout(std430, binding = SSBO_ITEM_CHUNKS) readonly buffer Chunks { vec4 chunk[]; };
layout(std430, binding = SSBO_ITEM_COMMANDS) writeonly buffer Commands { DrawCommand command[]; };
layout(std430, binding = SSBO_ITEM_COUNTS) writeonly buffer Counts { uint counts[]; };
uniform uint chunkCount;
uniform float farDistance;

bool chunkVisible(vec3 lo, vec3 hi, uint shooter, int face) {
  vec3 o = control.shooter[shooter].positionArea.xyz, n = control.shooter[shooter].normal.xyz;
  float slack = 1e-4 * farDistance, highest = -3.4e38;
#ifdef HEMICUBE
  vec4 least = vec4(3.4e38);  // per frustum side: the smallest excess of a corner beyond it
#else
  vec4 least = vec4(-3.4e38);  // one map of the whole hemisphere: no sides
#endif
  for (int k = 0; k < 8; ++k) {
    vec3 p = vec3((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y, (k & 4) != 0 ? hi.z : lo.z);
    vec3 local = shooterLocal(p, o, n);
    highest = max(highest, local.z);
#ifdef HEMICUBE
    vec3 f = cubeFace(local, face);
    least = min(least, vec4(f.x - f.z, -f.x - f.z, f.y - f.z, -f.y - f.z));
#endif
  }
  // itembuffer.vert clips below local.z = 1e-5 far.
  return highest >= 1e-5 * farDistance - slack && !any(greaterThan(least, vec4(slack)));
}

// One workgroup a layer walks the chunks in order, 64 at a time, and writes the visible ones
// commands packed at the front of the layer's slots (a scan in shared memory keeps the mesh's
// order, so the item buffer is the same as drawing every chunk), its count into counts[layer] and
// empty commands after them: a count draw (GL_ARB_indirect_parameters) reads only the count, a
// plain one reads every slot. On real_400k about a third of 400 chunks x 80 layers survive, and
// an idle slot cost the H200's front end ~0.7 us.
shared uint kept[64];

void main() {
  uint lane = gl_LocalInvocationID.x, layer = gl_WorkGroupID.y, base = layer * chunkCount;
  uint shooter = layer / uint(ITEM_FACES);
  bool live = activeShooter(shooter);
  uint written = 0u;
  for (uint first = 0u; first < chunkCount; first += 64u) {
    uint c = first + lane;
    vec4 lo = c < chunkCount ? chunk[2u * c] : vec4(0.0), hi = c < chunkCount ? chunk[2u * c + 1u] : vec4(0.0);
    bool drawn = c < chunkCount && live && chunkVisible(lo.xyz, hi.xyz, shooter, int(layer % uint(ITEM_FACES)));
    kept[lane] = drawn ? 1u : 0u;
    barrier();
    for (uint step = 1u; step < 64u; step <<= 1) {  // inclusive scan
      uint add = lane >= step ? kept[lane - step] : 0u;
      barrier();
      kept[lane] += add;
      barrier();
    }
    if (drawn)
      command[base + written + kept[lane] - 1u] =
          DrawCommand(floatBitsToUint(hi.w), 1u, floatBitsToUint(lo.w), 0, layer);
    written += kept[63];
    barrier();  // kept[] is read before the next round writes it
  }
  for (uint c = written + lane; c < chunkCount; c += 64u) command[base + c] = DrawCommand(0u, 0u, 0u, 0, layer);
  if (lane == 0u) counts[layer] = written;
}
