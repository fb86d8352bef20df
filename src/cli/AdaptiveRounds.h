// `--subdivide adaptive`'s rounds (src/scene/Leaves.h, src/solver/Subdivide.h): solve the layout
// (to roundStop's convergence at most), count steep texels per leaf on the GPU, split, lay out the
// refined scene and atlas, until no leaf splits or every split leaf is at --leaf-depth. The caller
// then solves the final layout from scratch, to its stop rule: every element's B comes from one
// solve, exact for its layout (no inherited error).
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "src/method/MethodUnit.h"
#include "src/scene/Camera.h"
#include "src/scene/Leaves.h"
#include "src/solver/Subdivide.h"

namespace hemirad {

struct AdaptiveRound {
  std::size_t elements = 0, leaves = 0, split = 0;
  unsigned shots = 0;
  double convergence = 0, ms = 0;
  std::string reached;  // the method's account of its solve (MethodUnit::reached)
};

struct AdaptiveLayout {
  std::optional<RefinedLayout> refined;  // none when no leaf split: the base layout stands
  std::unique_ptr<Atlas> atlas;
  std::vector<AdaptiveRound> rounds;
  std::size_t leaves = 0;  // of the final layout
};

// base: the uniform atlas of `scene` (it must outlive the call).
AdaptiveLayout refineAdaptively(const SubdivideOptions& options, const AtlasMethod& method, const Scene& scene,
                                const Atlas& base, const Camera& camera, double aspect, int maxTextureSize,
                                double chartAngle);

}  // namespace hemirad
