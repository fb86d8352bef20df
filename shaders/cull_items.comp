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

void main() {
  uint c = gl_GlobalInvocationID.x, layer = gl_GlobalInvocationID.y;
  if (c >= chunkCount) return;
  vec4 lo = chunk[2u * c], hi = chunk[2u * c + 1u];
  uint shooter = layer / uint(ITEM_FACES);
  bool drawn = activeShooter(shooter) && chunkVisible(lo.xyz, hi.xyz, shooter, int(layer % uint(ITEM_FACES)));
  command[layer * chunkCount + c] =
      DrawCommand(floatBitsToUint(hi.w), drawn ? 1u : 0u, floatBitsToUint(lo.w), 0, layer);
}
