// Seed 004 §5.5.2's shooting-locations vector: the blocks with table entries for the surfaces
// becoming visible, i.e. that shot since one of those surfaces' epochs began.
layout(local_size_x = 256) in;
layout(std430, binding = 7) readonly buffer ShotSoFar { vec4 shotSoFar[]; };
layout(std430, binding = 8) readonly buffer Snapshots { vec4 snapshot[]; };
layout(std430, binding = 9) writeonly buffer Pending { uint pending[]; };
uniform uint blockCount;
uniform uint epochCount;
uniform uint epochs[64];

void main() {
  uint b = gl_GlobalInvocationID.x;
  if (b >= blockCount) return;
  bool any = false;
  for (uint k = 0u; k < epochCount; ++k) any = any || shotSoFar[b].rgb != snapshot[epochs[k] * blockCount + b].rgb;
  pending[b] = any ? 1u : 0u;
}
