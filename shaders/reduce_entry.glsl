// The shooter reduction: the `keep` blocks with the largest unshot power (seed 003's batching
// shoots several a pass) and the total unshot power (for the convergence), folded in a fixed
// order so both are bitwise reproducible. A workgroup ranks up to 1024 entries; the top `keep`
// of every group contain the top `keep` of all, so levels of groups give the exact answer.
// Needs scene.glsl, hemisphere.glsl (luminance) and shooter_tree.glsl (node_stats.comp's sums,
// written this pass) included first. Local size must be 256.

struct Entry {
  float power;  // unshot power of the block
  uint index;   // the block
  float sum;    // total unshot power of the entries folded into this one
  float pad;
};

layout(std430, binding = SSBO_REDUCE_IN) readonly buffer In { Entry src[]; };
uniform uint count;       // entries (or blocks) to fold
uniform bool fromBlocks;  // first level: compute the entries from the blocks
uniform uint keep;        // entries kept per group: the shooters a pass takes
// What blocks are ranked by: 0 unshot power; 1 unshot power x (the block's largest received importance I - R +
// importanceFloor), the importance-driven choice (seed 004 §4.2.4, a max-map over the block);
// 2 |unshot importance| x area, for the importance shooters.
uniform uint rankBy;
uniform float importanceFloor;

const uint GROUP_ENTRIES = 1024u;
shared float rankPower[GROUP_ENTRIES];
shared uint rankIndex[GROUP_ENTRIES];
shared float groupSum[256];

// Block i: its ranking key and its unshot power luminance(dB) A.
Entry blockEntry(uint i) {
  NodeStats s = stats[i];
  float power = luminance(s.unshot.rgb);
  float key = rankBy == 0u ? power : rankBy == 1u ? power * (s.range.z + importanceFloor) : abs(s.unshot.a);
  return Entry(key, i, power, 0.0);
}

Entry loadEntry(uint i) { return fromBlocks ? blockEntry(i) : src[i]; }

// Slot a ranks before slot b: more power first, ties to the lower block (a total order).
bool ranksBefore(uint a, uint b) {
  return rankPower[a] > rankPower[b] || (rankPower[a] == rankPower[b] && rankIndex[a] < rankIndex[b]);
}

void swapSlots(uint a, uint b) {
  float p = rankPower[a];
  uint i = rankIndex[a];
  rankPower[a] = rankPower[b], rankIndex[a] = rankIndex[b];
  rankPower[b] = p, rankIndex[b] = i;
}

void sync() {
  memoryBarrierShared();
  barrier();
}

// Ranks entries [first, end) (at most 1024): afterwards slots 0..keep-1 hold the best in order
// (entries of power -1 past the last one) and groupSum[0] the total, for every thread.
void rankGroup(uint first, uint end) {
  uint l = gl_LocalInvocationID.x;
  float sum = 0.0;
  vec4 power;  // this thread's four entries, kept for placing them below
  uvec4 index;
  for (uint k = 0u; k < GROUP_ENTRIES / 256u; ++k) {
    uint slot = l + 256u * k, i = first + slot;
    Entry e = i < end ? loadEntry(i) : Entry(-1.0, 0xFFFFFFFFu, 0.0, 0.0);
    rankPower[slot] = power[k] = e.power;
    rankIndex[slot] = index[k] = e.index;
    sum += e.sum;
  }
  groupSum[l] = sum;
  if (keep == 1u)  // one shooter: a max tree is enough; first each thread's four slots into slot l
    for (uint k = 1u; k < GROUP_ENTRIES / 256u; ++k)
      if (ranksBefore(l + 256u * k, l)) swapSlots(l, l + 256u * k);
  sync();
  for (uint stride = 128u; stride > 0u; stride >>= 1) {
    if (l < stride) {
      groupSum[l] += groupSum[l + stride];
      if (keep == 1u && ranksBefore(l + stride, l)) swapSlots(l, l + stride);
    }
    sync();
  }
  if (keep == 1u) return;
  // Several shooters: an entry's place is the count of entries that rank before it (a total
  // order: places are distinct), counted only up to `keep`, the places kept, so all but the
  // best few stop early. Three barriers where a bitonic sort of the 1024 slots took 55, each of
  // which llvmpipe pays by switching through every invocation; the same places, bitwise.
  uint n = end - first;
  uvec4 place = uvec4(keep);
  for (uint k = 0u; k < GROUP_ENTRIES / 256u; ++k) {
    uint slot = l + 256u * k, before = 0u;
    if (slot >= n) break;
    for (uint j = 0u; j < n && before < keep; ++j)
      if (ranksBefore(j, slot)) ++before;
    place[k] = before;
  }
  sync();  // every place is counted before the slots are overwritten
  if (l < keep) rankPower[l] = -1.0, rankIndex[l] = 0xFFFFFFFFu;  // fewer entries than keep
  sync();
  for (uint k = 0u; k < GROUP_ENTRIES / 256u; ++k)
    if (place[k] < keep) rankPower[place[k]] = power[k], rankIndex[place[k]] = index[k];
  sync();
}
