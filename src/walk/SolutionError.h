// How far a solution is from a reference, for the method comparison and the animation: the
// RMS over the non-emitting elements (area-weighted) of luminance(B) - luminance(R), relative
// to their mean luminance(R). Emitters are left out (their B is nearly E from the start and
// would drown the indirect light), and the error is not relative per element (elements in
// deep shadow, nearly black in R, would make any noise look huge).
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

double relativeRmsError(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                        const std::vector<glm::vec4>& reference);

}  // namespace hemirad
