// The order in which the gather visits receiver texels, in workgroups of `group` texels: along a
// Morton curve through the scene's bounds, so a workgroup holds neighbouring surface points, whose
// segments to a shooter walk nearly the same BVH nodes side by side, and the workgroups themselves
// in bit-reversed order: llvmpipe hands each of its threads an equal contiguous run of a
// dispatch's workgroups, and along the curve (or the atlas) one run could hold the cheap walls and
// another the costly furniture (one core idled for a third of real_400k's gather). A GPU balances
// its own work; there the curve measured the same as the atlas's 8 x 8 tiles or up to 5 % faster
// (H100, to 90 %: real_400k at 100k elements 668 against 702 ms, real_1m 1,311 against 1,312 ms).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace hemirad {

struct Atlas;

// Every texel of a polygon (the gather's receivers), as x | y << 16; the last workgroup may be short.
std::vector<std::uint32_t> receiverOrder(const Atlas& atlas, glm::dvec3 lo, glm::dvec3 hi, unsigned group);

}  // namespace hemirad
