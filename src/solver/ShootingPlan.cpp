#include "src/solver/ShootingPlan.h"

#include <algorithm>
#include <cmath>

namespace hemirad {

namespace {

// Shooter block sides as fractions of the scene's largest extent (rounded down to a power of two
// texels): about 4 x 4 blocks or more on a wall the size of the scene, 16 x 16 on an emitter that
// size. A Cornell box then needs 208 to 496 shots to 90 % at 10k to 1M elements
// (docs/bench/h200-2026-12-02.md).
constexpr double kShooterSide = 1.0 / 4, kEmitterSide = 1.0 / 16;
// A curved chart's block shoots from one eye with its facets' mean normal, which its facets turn
// away from: from the blocks above a concave bowl lost 2.7 % of its light against element-by-element
// shooting, real_20k's armchairs 1.3-2.1 % at 20k elements; from 2 x 2 texels the bowl is
// within 0.1 % and every real_20k object within 0.7 % (docs/real-scenes.md#curved-shooters).
constexpr int kCurvedLevel = 1;
// Refined blocks pay where they hold many elements: a block's shot stands for its elements'
// shots, but near it (--refine-near) it is shot part by part, a shot several times an element's
// (10 x on llvmpipe). Where the planned blocks would hold fewer elements than this on average
// (few elements, or a scene of many small charts, whose blocks are the charts) and the solve
// refines within fewer than kWideReach sides, every element shoots; refined within kWideReach or
// more, nearly every receiver is near such small blocks and they shoot as elements do, and an
// unrefined solve (below --converge 0.99) keeps its cheap blocks. real_20k at 10k elements (4.9 a
// block), quick images against the path tracer, interiors: element by element 1.38 against 1.57 %
// (H100, 5.8 against 5.2 s) and 0.70 against 0.92 % (llvmpipe, 125 against 202 s); at 2,500 (2.0
// a block) 2.63 against 3.10 % (1.7 against 2.3 s). Only some charts one by one (the curved ones)
// was worse than either plan. Cornell box: 3.6 a block at 1,000 elements, 13 at 2,500
// (docs/design.md#elements-per-block).
constexpr double kMinElementsPerBlock = 6, kWideReach = 8;
// Item-buffer pixels per element across the scene's extent: a receiver element at the far side
// of the scene spans ~2 pixels of the item buffer (whose disc diameter covers pi radians at most).
constexpr double kPixelsPerElement = 4.0;
// The hemicube's straight edges are exact, and its buffer only nominates occluders for exact
// segment tests (shaders/visibility.glsl), so it needs to resolve occluders, not receivers: a
// quarter of the hemisphere's side. Cornell box, hemicube 128^2 against CGAL: 99.996 % of pairs
// agree at 10k and at 100k elements (docs/bench/h200-2026-12-02.md).
constexpr int kHemicubeDivisor = 4;
constexpr int kMinResolution = 128, kMaxResolution = 1024, kMaxLevel = 8;

int levelFor(double side, double texelSize) {
  return std::clamp(int(std::floor(std::log2(side / texelSize))), 0, kMaxLevel);
}

int powerOfTwoAtLeast(double x) {
  int r = 1;
  while (r < x && r < kMaxResolution) r *= 2;
  return r;
}

}  // namespace

ShootingPlan planShooting(const Scene& scene, const Atlas& atlas, int shootLevel, int itemResolution,
                          Projection projection, double refineNear) {
  const glm::dvec3 size = scene.boundsMax() - scene.boundsMin();
  const double extent = std::max({size.x, size.y, size.z});
  ShootingPlan plan;
  for (const Chart& c : atlas.charts) {
    const bool emitter = scene.materials[scene.polygons()[std::size_t(c.polygon)].material].emissive();
    const int level = levelFor(extent * (emitter ? kEmitterSide : kShooterSide), c.cellSize);
    plan.chartLevel.push_back(shootLevel != kAutoShootLevel ? shootLevel
                              : c.planar                    ? level
                                                            : std::min(level, kCurvedLevel));
  }
  const bool fewSidesNear = refineNear > 0 && refineNear < kWideReach;
  if (shootLevel == kAutoShootLevel && fewSidesNear &&
      double(atlas.elements) < kMinElementsPerBlock * double(atlas.shooterBlocks(plan.chartLevel).size()))
    std::fill(plan.chartLevel.begin(), plan.chartLevel.end(), 0);
  // Refined leaves (src/scene/Leaves.h) see at their own cells' scale; but the hemicube resolves
  // occluders, which a leaf split does not make smaller: it is planned from the base cells
  // (adaptive Cornell at 100k elements: 128^2, not 256^2, as uniform subdivision at 100k).
  const bool hemicube = projection == Projection::Hemicube;
  double finest = atlas.texelSize;
  if (!hemicube)
    for (const Chart& c : atlas.charts) finest = std::min(finest, c.cellSize);
  const int divisor = hemicube ? kHemicubeDivisor : 1;
  plan.itemResolution =
      itemResolution != kAutoItemResolution
          ? itemResolution
          : std::max(kMinResolution, powerOfTwoAtLeast(kPixelsPerElement * extent / finest) / divisor);
  return plan;
}

}  // namespace hemirad
