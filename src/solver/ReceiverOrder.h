// The order in which the gather visits receiver texels. Along a Morton curve through the scene's
// bounds, in workgroups of `group` texels: a workgroup holds neighbouring surface points, whose
// segments to a shooter walk nearly the same BVH nodes side by side (a GPU's warp, llvmpipe's SIMD
// row), where the atlas's own order puts texels of charts far apart side by side. The workgroups
// themselves go in bit-reversed order: llvmpipe hands each of its threads an equal contiguous
// run of a dispatch's workgroups, and along the curve one run could hold the cheap walls and
// another the costly furniture (one core idled for a third of real_400k's gather).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace hemirad {

struct Atlas;

// Every texel of a polygon (the gather's receivers), as x | y << 16; the last workgroup may be short.
std::vector<std::uint32_t> receiverOrder(const Atlas& atlas, glm::dvec3 lo, glm::dvec3 hi, unsigned group);

}  // namespace hemirad
