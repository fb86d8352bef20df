// Adaptive subdivision's refinement step (issue 31, seed 003 section 39.3.2; the layout is
// src/scene/Leaves.h): after a solve, shaders/gradient.comp counts per leaf the texels whose
// radiosity changes by more than `threshold` of their own per cell; leaves with `count` such
// texels or more split. Cells halve at each depth, so a smooth gradient's change per cell halves
// too and stops splitting, while a shadow edge or a contact keeps its jump and splits to the
// maximum depth.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gl/Objects.h"
#include "src/scene/Leaves.h"
#include "src/solver/Solver.h"
#include "src/solver/SolverState.h"

namespace hemirad {

struct SplitRule {
  double threshold = 0.1;  // relative luminance change per cell (--split-gradient)
  // Texels over it that split a leaf: a line across a 16-cell leaf flags 16 to 32.
  unsigned count = kLeafCells / 2;
  // Luminance under which changes count as this floor's: darkFraction of the area-mean B.
  double darkFraction = 0.01;
};

struct SubdivideOptions {
  bool adaptive = false;  // --subdivide adaptive
  int maxDepth = 2;       // --leaf-depth
  SplitRule rule;
  // The final layout's elements at most (--elements; 0 under --texel-size: no bound). The first
  // round lays out a quarter of them, leaving the rest to the splits.
  std::size_t budget = 0;
  static constexpr std::size_t kFirstRoundShare = 4;
};

// An adaptive round's stop rule: a convergence target above kRoundConvergence stops there. A
// round only decides which leaves split, and the steep places (shadow edges, contacts, a light's
// outline) are drawn by the first shots, the direct light's; the final layout is solved to the
// full rule. Cornell box, 10k elements to 0.999 on llvmpipe: every region's error against the
// path-traced reference the same to 0.03 points (within its noise), the rounds 2.8 -> 0.6 s;
// 100k to 0.9: 8.7 -> 6.2 s (docs/adaptive.md).
inline constexpr double kRoundConvergence = 0.8;
inline StopRule roundStop(StopRule stop) {
  if (stop.targetConvergence > kRoundConvergence) stop.targetConvergence = kRoundConvergence;
  return stop;
}

// Elements a layout has and may grow to: a split leaf's texels count four times over (each
// quarter keeps its cell count).
struct ElementBudget {
  std::size_t elements = 0, most = 0;     // most 0: no bound
  std::vector<std::size_t> leafElements;  // per tree node, the texels of the layout it holds
};

// The relative-change floor: rule.darkFraction of the area-weighted mean luminance of B.
float darkestLuminance(const Atlas& atlas, const std::vector<glm::vec4>& B, const SplitRule& rule);

// The GPU pass (needs a current GL context).
class GradientPass {
 public:
  GradientPass();
  // Per tree node, its texels over the threshold (leafOf: leafOfTexel of state.atlas).
  std::vector<unsigned> count(const SolverState& state, const std::vector<std::int32_t>& leafOf, std::size_t nodes,
                              float threshold, float darkest) const;

 private:
  gl::Program program_;
};

// How luminanceSlope takes a texel with neighbours on both sides: their central difference
// (gradient.comp's), or minmod, as finite-volume schemes limit slopes: the smaller one-sided
// difference where both agree in sign, else 0. A linear profile with a central difference
// overshoots at a kink (an element in a contact shadow's umbra beside its penumbra: the
// penumbra's slope, extrapolated into the umbra) and at an extremum; a limited one does not.
enum class SlopeRule { Central, Limited };
// Minmod of two one-sided changes (each toward its neighbour, per step, signed along the axis): the
// smaller where they agree in sign, else 0. SlopeRule::Limited's.
inline double limitedSlope(double up, double down) {
  return up * down <= 0 ? 0.0 : (std::abs(up) < std::abs(down) ? up : down);
}
// The monotonized central limiter (van Leer 1977) of a texel's one-sided changes (signed along the
// axis, per cell; `upStep` and `downStep` the distances to the neighbours, in cells): where they
// agree in sign, the slope at the texel of the parabola through the three means (their
// distance-weighted mean: the central difference for even steps), at most twice the smaller;
// else 0. Inside smooth light it is second order, where minmod takes the flatter side: beside a
// crease or a contact the light steepens toward the edge, and the flatter side leaves the piece
// too bright there. A kink (an umbra beside its penumbra) and a peak stay flat, and no profile
// passes its neighbours' light. The near gather's profiles' (src/output/GatherSources.cpp).
inline double centralLimitedSlope(double up, double down, double upStep = 1, double downStep = 1) {
  if (up * down <= 0) return 0.0;
  const double central = (downStep * up + upStep * down) / (upStep + downStep);
  return std::copysign(std::min(2 * std::min(std::abs(up), std::abs(down)), std::abs(central)), up);
}
// At a chart's edge, the slope at the outer texel of the parabola through it and its next two
// (`near` and `far`: the one-sided changes to the next and from the next to the one after, `step`
// and `farStep` apart), within 0 and twice `near` where both agree in sign, else `near`: the light
// steepening toward a crease is followed as inside.
inline double edgeSlope(double near, double far, double step, double farStep) {
  if (near * far <= 0) return near;
  const double parabola = near - step * (far - near) / (step + farStep);
  return near * std::clamp(parabola / near, 0.0, 2.0);
}

// The change of B's luminance per texel step at texel t along the atlas's x and y, within t's
// chart: by `rule` inside it, one-sided at the chart's edge, 0 without a neighbour.
glm::vec2 luminanceSlope(const Atlas& atlas, const std::vector<glm::vec4>& B, glm::ivec2 t,
                         SlopeRule rule = SlopeRule::Central);

// The same count on the CPU from a B readback (the pass's twin: tests, and adaptive rounds under
// --direct per-pixel, which count B minus the direct light: src/cli/AdaptiveRounds.cpp).
std::vector<unsigned> countSteepTexels(const Atlas& atlas, const std::vector<glm::vec4>& B,
                                       const std::vector<std::int32_t>& leafOf, std::size_t nodes, float threshold,
                                       float darkest);

// Splits the leaves with counts >= rule.count (below the maximum depth), steepest first (ties: the
// lower node), skipping any whose split would take the layout past budget.most; returns how many split.
std::size_t splitSteepLeaves(LeafTree& tree, const std::vector<unsigned>& counts, const SplitRule& rule,
                             const ElementBudget& budget = {});
// Per tree node, the texels of leafOf (leafOfTexel) in it.
std::vector<std::size_t> leafElements(const std::vector<std::int32_t>& leafOf, std::size_t nodes);

}  // namespace hemirad
