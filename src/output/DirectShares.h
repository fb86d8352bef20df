// The per-pixel pass (src/output/Renderer.cpp) in shares. llvmpipe ends all of a shader
// invocation's loops after 65,535 turns in all (shaders/bvh.glsl), which a pixel's walks to the
// emitters (a furnished room's ceiling panels seen past its clutter) or its near gather beside a
// crease can pass. In shares, a draw adds a part of the direct light or gathers a part of the
// blocks, so each invocation's loops take a share's turns. The direct light's unit is a strip: one
// row of a piece's G x G visibility cells (shaders/direct.glsl), strip s = piece * G + row.
#pragma once
#include <vector>

namespace hemirad {

// The shares each part is drawn in: 1 and 1 draw both together.
struct SharePlan {
  unsigned direct = 1, gather = 1;
  bool operator==(const SharePlan&) const = default;
};

// One draw's strips [stripsFirst, stripsEnd) and gather blocks [blocksFirst, blocksEnd).
struct DirectShare {
  unsigned stripsFirst = 0, stripsEnd = 0, blocksFirst = 0, blocksEnd = 0;
};

// The draws of a plan over `pieces` emitter pieces of `grid` strips and `blocks` gather blocks:
// one of all for the plan {1, 1}; else the direct light in min(plan.direct, strips) draws (whole
// pieces while there are as many pieces as draws), then the blocks in min(plan.gather, blocks),
// each as even as whole units allow. Every strip and block is in one draw.
std::vector<DirectShare> directShares(SharePlan plan, unsigned pieces, unsigned grid, unsigned blocks);

}  // namespace hemirad
