// How coarse the shooters are and how fine their item buffers. Fixed by the user, or (auto)
// chosen from the scene so that the shots a solve needs stay about the same however finely the
// receivers are cut: coarse shooters, fine receivers. The exact polygon form factor makes a large
// block's transfer exact; only its visibility is taken from one point, its centre. Emitters shoot
// four times finer than the rest, so direct shadows keep their penumbrae; curved charts from 2 x 2
// texels at most, their facets turning away from a block's one normal. In a solve refined a few
// sides near its shooters, where blocks would hold few elements each, every element shoots
// (kMinElementsPerBlock).
#pragma once
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"
#include "src/solver/Projection.h"

namespace hemirad {

inline constexpr int kAutoShootLevel = -1;     // ProgressiveSettings::shootLevel
inline constexpr int kAutoItemResolution = 0;  // ProgressiveSettings::itemResolution

struct ShootingPlan {
  std::vector<int> chartLevel;  // per chart: it shoots from 2^level x 2^level texel blocks
  int itemResolution = 512;     // item buffer pixels a side
};

// shootLevel >= 0 and itemResolution > 0 are taken as given; the auto values are planned.
// `refineNear`: how near its shooters the solve refines (--refine-near, as it runs; 0 none), which
// auto's level weighs.
ShootingPlan planShooting(const Scene& scene, const Atlas& atlas, int shootLevel, int itemResolution,
                          Projection projection = Projection::Orthographic, double refineNear = 0);

}  // namespace hemirad
