// The split of a progressive solution into direct and indirect light (issue 31, `--direct
// per-pixel`, docs/design.md#per-pixel-direct). Camera images then compute the direct light per
// pixel, exactly, and take only the indirect part from the elements. Subtracting a point-evaluated
// direct term from an element's averaged B would leave wrong, even negative, values where light
// varies across the element (shadow edges); instead the elements' direct part comes from the same
// machinery: a progressive solve with the same plan in which receivers keep what they receive in
// B but never shoot it again (gather.comp's DIRECT_ONLY), so only the emitters shoot, once. Its B
// is E + direct light, element by element, discretised exactly as the full solve's first shots,
// and B_full - B_direct is the light of two and more bounces (E cancels).
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"
#include "src/solver/ProgressiveSolver.h"

namespace hemirad {

// B of the emitters' light alone: E + direct, per element (atlas order). `settings` are the full
// solve's (its plan; its shot budget, so a solve cut short by --shots is split consistently);
// an importance-driven solve is driven by `camera` as the full one was.
std::vector<glm::vec4> directOnlyRadiosity(const Scene& scene, const Atlas& atlas, ProgressiveSettings settings,
                                           const Camera& camera, double aspect);

// B - direct, rgb (alpha: B's), per element: the light that arrived after at least one reflection.
std::vector<glm::vec4> indirectPart(const std::vector<glm::vec4>& B, const std::vector<glm::vec4>& direct);

}  // namespace hemirad
