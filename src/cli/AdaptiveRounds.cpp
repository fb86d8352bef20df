#include "src/cli/AdaptiveRounds.h"

#include <fmt/format.h>
#include <chrono>
#include <numeric>

#include "src/solver/DirectSplit.h"

namespace hemirad {

namespace {

// One round: solve `atlas` to the method's stop rule and count each leaf's steep texels; `budget`
// gets the layout's elements per leaf.
std::vector<unsigned> solveAndCount(const SubdivideOptions& o, const AtlasMethod& method, const Scene& scene,
                                    const Atlas& atlas, const std::vector<int>& baseChart, const LeafTree& tree,
                                    const Camera& camera, double aspect, AdaptiveRound& round, ElementBudget& budget) {
  const auto t0 = std::chrono::steady_clock::now();
  SolverState state(scene, atlas);
  const std::unique_ptr<AtlasRun> run = method.startRound(state);
  run->look(camera, aspect);
  const SolveStatus solved = advanceToStop(run->solver(), {});
  round.shots = solved.shots;
  round.convergence = solved.convergence;
  round.reached = run->reached(solved);
  const std::vector<glm::vec4> B = state.readRadiosity();
  const std::vector<std::int32_t> leafOf = leafOfTexel(atlas, baseChart, tree);
  // Under --direct per-pixel images take only the indirect light from the elements: split on it.
  const std::vector<glm::vec4> direct = run->directOnly(camera, aspect);
  std::vector<unsigned> counts;
  if (direct.empty())
    counts = GradientPass().count(state, leafOf, tree.nodes().size(), float(o.rule.threshold),
                                  darkestLuminance(atlas, B, o.rule));
  else {
    const std::vector<glm::vec4> indirect = indirectPart(B, direct);
    counts = countSteepTexels(atlas, indirect, leafOf, tree.nodes().size(), float(o.rule.threshold),
                              darkestLuminance(atlas, indirect, o.rule));
  }
  budget = {atlas.elements, o.budget, leafElements(leafOf, tree.nodes().size())};
  round.elements = atlas.elements;
  round.leaves = tree.leafCount();
  round.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return counts;
}

}  // namespace

AdaptiveLayout refineAdaptively(const SubdivideOptions& o, const AtlasMethod& method, const Scene& scene,
                                const Atlas& base, const Camera& camera, double aspect, int maxTextureSize,
                                double chartAngle) {
  AdaptiveLayout out;
  LeafTree tree(base, o.maxDepth);
  std::vector<int> baseChart(base.charts.size());
  std::iota(baseChart.begin(), baseChart.end(), 0);
  for (int depth = 0; depth < o.maxDepth; ++depth) {
    AdaptiveRound& round = out.rounds.emplace_back();
    const Scene& s = out.refined ? out.refined->scene : scene;
    const Atlas& a = out.atlas ? *out.atlas : base;
    ElementBudget budget;
    const std::vector<unsigned> counts = solveAndCount(o, method, s, a, baseChart, tree, camera, aspect, round, budget);
    round.split = splitSteepLeaves(tree, counts, o.rule, budget);
    fmt::print(stderr, "hemirad: adaptive round {}: {} elements, {} leaves, {} in {:.0f} ms; {} leaves split\n", depth,
               round.elements, round.leaves, round.reached, round.ms, round.split);
    if (round.split == 0) break;
    RefinedLayout next = refineLayout(scene, tree);
    out.atlas =
        std::make_unique<Atlas>(buildAtlas(next.scene, next.specs, base.texelSize, maxTextureSize, 0, chartAngle));
    baseChart = next.specChart;
    out.refined = std::move(next);
  }
  out.leaves = tree.leafCount();
  return out;
}

}  // namespace hemirad
