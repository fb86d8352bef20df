// What the near final gather (shaders/near_gather.glsl) knows of each node of its shooter trees:
// the mean light its elements send on, where that light sits, and for a single element of a planar
// chart its piece's half-axes and the change of its light across them, which the gather spreads
// over the piece (docs/design.md#final-gather).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "src/scene/Atlas.h"
#include "src/solver/ShooterTree.h"

namespace hemirad {

// Four vec4s a node, node_stats.comp's layout: [0] the area-weighted mean of `sent` (rgb); [1] the
// sums of w x and of w, w = luminance(sent) A (its light's centre, the origin of its visibility: a
// node half under a block sends from its lit half); for a single element of a planar projection
// chart [2] and [3] its piece's half-axes u and v (u x v along the node's normal) and in w the
// change of its luminance across the piece along that axis (end to end), relative to its own
// (0 elsewhere: its light constant across it).
std::vector<glm::vec4> gatherSources(const Atlas& atlas, const std::vector<ShooterNode>& nodes,
                                     const std::vector<glm::vec4>& sent);

}  // namespace hemirad
