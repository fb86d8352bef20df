// Bench fill ceiling (src/bench/Ceilings.cpp): the item buffer's writes (an id and the depth
// test) without its exact per-pixel depth, so the ceiling is the device's raw fill rate and the
// item buffer's fraction of it shows what its fragment work costs.
flat in uint vPolygon;
layout(location = 0) out uint itemId;
void main() { itemId = vPolygon; }
