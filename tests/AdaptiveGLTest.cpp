#include <fmt/format.h>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "src/cli/AdaptiveRounds.h"
#include "src/cli/Solve.h"
#include "src/method/Registry.h"
#include "src/output/SeamStitch.h"
#include "src/scene/ItemMesh.h"
#include "src/scene/Leaves.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Checkpoint.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/ShootingPlan.h"
#include "src/solver/Subdivide.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// A 4 x 4 floor (y = 0) lit by a 0.1-wide lamp 2 above its centre, with a 0.3-wide blocker half
// way: a 0.6-wide shadow with a 0.1 penumbra in the floor's middle, and a smooth 1/r^2 falloff
// elsewhere (at most ~0.06 relative change per 1/16 cell).
Scene shadowScene() {
  Scene s;
  const int grey = test::material(s, 0.5, 0.0), lamp = test::material(s, 0.0, 100.0);
  const glm::dvec3 X(1, 0, 0), Z(0, 0, 1);
  s.addPolygon(test::rectangle({-2, 0, -2}, Z, X, 4, 4), grey, s.addObject("floor"));  // faces up
  s.addPolygon(test::rectangle({-0.15, 1, -0.15}, Z, X, 0.3, 0.3), grey, s.addObject("blocker"));
  s.addPolygon(test::rectangle({-0.05, 2, -0.05}, X, Z, 0.1, 0.1), lamp, s.addObject("lamp"));  // faces down
  return s;
}

constexpr double kTexel = 4.0 / 64;  // the floor: 64 x 64 cells, 4 x 4 leaves

// The world centre of a node of base chart `chart`.
glm::dvec3 nodeCentre(const Atlas& base, const LeafNode& n) {
  const Chart& c = base.charts[std::size_t(n.chart)];
  const glm::dvec2 units(0.5 * (n.rect.x + n.rect.z), 0.5 * (n.rect.y + n.rect.w));
  return c.frame.lift(c.corner + units * (c.cellSize / kUnitsPerCell));
}

double areaSum(const Atlas& atlas) {
  double sum = 0;
  for (const glm::vec4& pa : atlas.positionArea) sum += pa.w;
  return sum;
}

struct SolvedRound {
  std::vector<unsigned> gpu, cpu;
};

// Solves `atlas` and counts steep texels per leaf both ways.
SolvedRound solveAndCount(const Scene& scene, const Atlas& atlas, const LeafTree& tree, const SplitRule& rule) {
  test::backend();
  SolverState state(scene, atlas);
  ProgressiveSettings settings;
  settings.stop.targetConvergence = 0.99;
  ProgressiveSolver solver(state, settings);
  advanceToStop(solver, {});
  std::vector<int> identity(atlas.charts.size());
  for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = int(i);
  const std::vector<std::int32_t> leafOf = leafOfTexel(atlas, identity, tree);
  const std::vector<glm::vec4> B = state.readRadiosity();
  const float darkest = darkestLuminance(atlas, B, rule);
  return {GradientPass().count(state, leafOf, tree.nodes().size(), float(rule.threshold), darkest),
          countSteepTexels(atlas, B, leafOf, tree.nodes().size(), float(rule.threshold), darkest)};
}

}  // namespace

TEST_CASE("Adaptive refinement splits the leaves a shadow edge crosses, not the smooth ones", "[gl][adaptive][slow]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 2);
  const SplitRule rule;
  const SolvedRound counts = solveAndCount(scene, base, tree, rule);
  // The GPU's atomic count is the CPU twin's, leaf for leaf.
  CHECK(counts.gpu == counts.cpu);
  REQUIRE(splitSteepLeaves(tree, counts.gpu, rule) > 0);
  int edgeTiles = 0, smoothTiles = 0, edgeSplit = 0, smoothSplit = 0;
  for (const LeafNode& n : tree.nodes()) {
    if (n.depth != 0 || base.charts[std::size_t(n.chart)].polygon != 0) continue;  // the floor's tiles
    const glm::dvec3 c = nodeCentre(base, n);
    const bool edge = std::abs(c.x) < 1 && std::abs(c.z) < 1;  // the shadow's square |x|, |z| <= 0.3
    (edge ? edgeTiles : smoothTiles)++;
    (edge ? edgeSplit : smoothSplit) += !n.leaf();
    INFO("tile at " << c.x << ", " << c.z << ": " << counts.gpu[std::size_t(&n - tree.nodes().data())] << " steep");
    CHECK(n.leaf() != edge);
  }
  CHECK(edgeTiles == 4);
  CHECK(smoothTiles == 12);
  CHECK(edgeSplit == 4);
  CHECK(smoothSplit == 0);
}

TEST_CASE("A refined layout keeps the surface: element areas sum to the scene's area", "[cpu][adaptive]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 2);
  REQUIRE(tree.split(0));  // a corner tile of the floor, then one of its quarters
  const int quarter = tree.nodes()[0].firstChild;
  REQUIRE(tree.split(quarter));
  CHECK_FALSE(tree.split(tree.nodes()[std::size_t(quarter)].firstChild));  // at the maximum depth
  const RefinedLayout refined = refineLayout(scene, tree);
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  CHECK(refined.scene.totalArea() == Approx(scene.totalArea()).epsilon(1e-12));
  CHECK(areaSum(atlas) == Approx(areaSum(base)).epsilon(1e-6));  // float areas
  // Each split quarter of the tile holds as many cells as the tile: three quarters and four sixteenths.
  const std::size_t split = base.elements - 16 * 16 + 3 * 16 * 16 + 4 * 16 * 16;
  CHECK(atlas.elements == split);
  CHECK(tree.leafCount() == 18 + 3 + 3);  // 16 floor tiles, the blocker's and the lamp's; two splits
  CHECK(atlas.layoutHash() != base.layoutHash());
}

TEST_CASE("A layout with no split leaf is the uniform one, texel for texel", "[cpu][adaptive]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  const RefinedLayout same = refineLayout(scene, LeafTree(base, 2));
  const Atlas atlas = buildAtlas(same.scene, same.specs, base.texelSize);
  CHECK(atlas.layoutHash() == base.layoutHash());
  CHECK(atlas.positionArea == base.positionArea);
}

TEST_CASE("A checkpoint of the uniform layout is refused by the refined one", "[cpu][adaptive]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 1);
  tree.split(0);
  const RefinedLayout refined = refineLayout(scene, tree);
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  auto identity = [](const Atlas& a) {
    // The same size on both sides: only the layout hash tells them apart.
    return nlohmann::json{{"atlas", {64, 64}}, {"atlas_layout", fmt::format("{:016x}", a.layoutHash())}};
  };
  CHECK_NOTHROW(checkResumable("same.ckpt", identity(base), identity(base)));
  CHECK_THROWS_WITH(checkResumable("uniform.ckpt", identity(base), identity(atlas)), Catch::Contains("atlas_layout"));
}

TEST_CASE("A closed box solved on a refined layout gives B = E / (1 - rho)", "[gl][adaptive]") {
  const Scene box = test::cube(0.5, 1.0);   // rho 0.5, E 1: B = 2
  const Atlas base = buildAtlas(box, 0.5);  // a 2 x 2-cell leaf per face
  LeafTree tree(base, 2);
  for (int face = 0; face < 6; ++face) {
    REQUIRE(tree.split(face));  // its quarters at 1/8, one of them at 1/16
    REQUIRE(tree.split(tree.nodes()[std::size_t(face)].firstChild + face % 4));
  }
  const RefinedLayout refined = refineLayout(box, tree);
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  test::backend();
  SolverState state(refined.scene, atlas);
  ProgressiveSettings settings;
  settings.stop.targetConvergence = 0.9995;  // what is left unshot lowers B by < 0.05%
  ProgressiveSolver solver(state, settings);
  advanceToStop(solver, {});
  const auto objects = objectRadiosity(refined.scene, atlas, state.readRadiosity());
  REQUIRE(objects.size() == 1);
  INFO(atlas.elements << " elements");
  CHECK(objects[0].mean.x == Approx(2.0).epsilon(0.001));
}

TEST_CASE("An element budget splits the steepest leaves first and keeps the refined layout within it",
          "[cpu][adaptive]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 2);
  std::vector<int> identity(base.charts.size());
  for (std::size_t i = 0; i < identity.size(); ++i) identity[i] = int(i);
  const std::vector<std::size_t> perLeaf = leafElements(leafOfTexel(base, identity, tree), tree.nodes().size());
  REQUIRE(perLeaf[0] == 256);  // the floor's 16 x 16-cell tiles
  // Three steep floor tiles, the least steep first; room for two splits (3 x 256 elements each) but not three.
  std::vector<unsigned> counts(tree.nodes().size(), 0);
  counts[0] = 10, counts[1] = 30, counts[2] = 20;
  const SplitRule rule;
  const ElementBudget budget{base.elements, base.elements + 2 * 3 * 256 + 100, perLeaf};
  CHECK(splitSteepLeaves(tree, counts, rule, budget) == 2);
  CHECK(tree.nodes()[0].leaf());  // the least steep waits
  CHECK_FALSE(tree.nodes()[1].leaf());
  CHECK_FALSE(tree.nodes()[2].leaf());
  const RefinedLayout refined = refineLayout(scene, tree);
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  CHECK(atlas.elements == base.elements + 2 * 3 * 256);
  CHECK(atlas.elements <= budget.most);
}

TEST_CASE("Bad input: an adaptive layout over the texture limit is one error naming the limit and what to lower",
          "[cpu][adaptive]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 1);
  REQUIRE(tree.split(0));
  const RefinedLayout refined = refineLayout(scene, tree);
  CHECK_THROWS_WITH(
      buildAtlas(refined.scene, refined.specs, base.texelSize, 64),
      Catch::Contains("texel atlas, over the GPU's limit of 64 texels a side") && Catch::Contains("--split-gradient"));
}

namespace {

// The refined scene's polygon under floor point (x, 0, z), or -1.
int polygonUnder(const Scene& scene, double x, double z) {
  for (std::size_t p = 0; p < scene.polygons().size(); ++p) {
    const Poly3& v = scene.polygons()[p].vertices;
    if (std::abs(v[0].y) > 1e-9) continue;
    bool inside = true;
    for (std::size_t i = 0; i < v.size() && inside; ++i) {
      const glm::dvec3 a = v[i], b = v[(i + 1) % v.size()];
      inside = (b.z - a.z) * (x - a.x) - (b.x - a.x) * (z - a.z) >= -1e-12;  // inside: counter-clockwise about +y
    }
    if (inside) return int(p);
  }
  return -1;
}

// The largest change between neighbouring lookups 1/64 of a base texel apart along z = z0 (x in
// [-2, 2)), the lookups Atlas::sample (shaders/camera.frag's twin) makes of `values`.
double largestStep(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& values, double z0) {
  double largest = 0, last = -1;
  for (double x = -1.99; x < 1.99; x += kTexel / 64) {
    const int p = polygonUnder(scene, x, z0);
    if (p < 0) continue;
    const double b = atlas.sample(values, p, atlas.atlasCoord(p, {x, 0, z0})).x;
    if (last >= 0) largest = std::max(largest, std::abs(b - last));
    last = b;
  }
  return largest;
}

}  // namespace

TEST_CASE("Lookups across leaves of different density show no step once seams are stitched", "[cpu][adaptive]") {
  // B = 1 + x / 4 on the floor: a smooth ramp, so any jump between lookups 1/64 of a texel apart
  // is the layout's, where a coarse tile meets its split neighbour's half-side texels.
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 2);
  REQUIRE(tree.split(5));  // a floor tile inside, then one of its quarters
  REQUIRE(tree.split(tree.nodes()[5].firstChild));
  const RefinedLayout refined = refineLayout(scene, tree);
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  std::vector<glm::vec4> B(atlas.positionArea.size(), glm::vec4(0.0f));
  for (std::size_t t = 0; t < B.size(); ++t)
    if (atlas.positionArea[t].w > 0) B[t] = glm::vec4(glm::vec3(1 + atlas.positionArea[t].x / 4), 0);
  const glm::dvec3 centre = nodeCentre(base, tree.nodes()[5]);
  const double ramp = kTexel / 64 / 4;  // the ramp's own change between lookups
  const double raw = largestStep(refined.scene, atlas, B, centre.z);
  const double stitched = largestStep(refined.scene, atlas, stitchSeams(refined.scene, atlas, B), centre.z);
  INFO("largest step " << raw << " unstitched, " << stitched << " stitched; the ramp's " << ramp);
  CHECK(raw > 10 * ramp);
  CHECK(stitched < 4 * ramp);  // measured 1.8: a kink where the densities meet, no step
}

TEST_CASE("A limited slope follows a ramp as the central difference does, and stays flat beside a kink and at a peak",
          "[cpu][adaptive]") {
  // A central difference beside a kink (an umbra beside its penumbra) would carry the ramp's slope
  // into the flat side. The near gather's profiles limit the central difference instead
  // (centralLimitedSlope, tests/GatherSourcesTest.cpp), which keeps the kink and the peak flat too.
  const Scene scene = shadowScene();
  const Atlas atlas = buildAtlas(scene, kTexel);
  const std::uint32_t floor = atlas.chartOf[0];
  auto slopes = [&](auto profile, double x) {  // at the floor texel whose centre is nearest world x, z ~ 0
    std::vector<glm::vec4> B(atlas.positionArea.size(), glm::vec4(0.0f));
    glm::ivec2 at(-1);
    double best = 1e9;
    for (int y = 0; y < atlas.height; ++y)
      for (int t = 0; t < atlas.width; ++t) {
        const std::size_t i = std::size_t(y) * atlas.width + t;
        if (atlas.chartAt(i) != floor || atlas.positionArea[i].w <= 0) continue;
        const glm::vec4 p = atlas.positionArea[i];
        B[i] = glm::vec4(glm::vec3(float(profile(double(p.x)))), 0);
        const double d = std::abs(p.x - x) + std::abs(p.z - 0.01);
        if (d < best) best = d, at = {t, y};
      }
    return std::pair{luminanceSlope(atlas, B, at), luminanceSlope(atlas, B, at, SlopeRule::Limited)};
  };
  const double step = kTexel / 4;  // the ramps' change per texel
  auto ramp = [](double x) { return 1 + x / 4; };
  const auto [rampCentral, rampLimited] = slopes(ramp, 0.5);
  CHECK(glm::length(rampCentral) == Approx(step).epsilon(1e-3));
  CHECK(glm::length(rampLimited - rampCentral) < 1e-6);
  const double x0 = 0.5 * kTexel;  // a texel centre (cells start at -2)
  auto kink = [x0](double x) { return 1 + std::max(0.0, x - x0) / 4; };
  const auto [kinkCentral, kinkLimited] = slopes(kink, x0);
  CHECK(glm::length(kinkCentral) == Approx(step / 2).epsilon(1e-3));
  CHECK(glm::length(kinkLimited) == 0);
  const auto [upCentral, upLimited] = slopes(kink, x0 + kTexel);  // on the ramp: both follow it
  CHECK(glm::length(upLimited) == Approx(step).epsilon(1e-3));
  auto peak = [x0](double x) { return 2 - std::abs(x - x0) / 4; };
  CHECK(glm::length(slopes(peak, x0).second) == 0);
  const auto [edgeCentral, edgeLimited] = slopes(ramp, -2 + kTexel / 2);  // the chart's edge: one-sided
  CHECK(glm::length(edgeLimited) == Approx(step).epsilon(1e-3));
  CHECK(glm::length(edgeLimited - edgeCentral) < 1e-6);
}

// A round only decides where leaves split, which the first shots (the direct light) show: it
// stops at kRoundConvergence, the final layout's solve at the stop rule (docs/adaptive.md).
TEST_CASE("Adaptive rounds solve to the round convergence, not to the stop rule", "[gl][adaptive]") {
  gl::RenderBackend& backend = test::backend();
  const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  std::vector<std::unique_ptr<MethodUnit>> methods = makeMethods();
  auto* progressive = dynamic_cast<AtlasMethod*>(methods.front().get());
  REQUIRE(progressive);
  REQUIRE(progressive->name() == "progressive");
  SolveOptions o;
  progressive->settle(o);  // the default stop rule: 90 % converged
  REQUIRE(progressive->stop().targetConvergence == Approx(0.9));
  const Atlas base = buildAtlas(scene, texelSizeForElements(scene, 500));
  SubdivideOptions options;
  options.adaptive = true;
  options.budget = 2000;
  const AdaptiveLayout layout = refineAdaptively(options, *progressive, scene, base, resolveCamera(scene, std::nullopt),
                                                 1.0, backend.maxTextureSize(), 30.0);
  REQUIRE(!layout.rounds.empty());
  SolverState state(scene, base);  // the first round's layout, solved to the stop rule
  const SolveStatus full = advanceToStop(progressive->start(state)->solver(), {});
  CHECK(full.convergence >= 0.9);
  const AdaptiveRound& first = layout.rounds.front();
  CHECK(first.convergence >= kRoundConvergence);
  CHECK(first.convergence < 0.9);
  CHECK(first.shots < full.shots);
  for (const AdaptiveRound& r : layout.rounds) CHECK(r.convergence < 0.9);
}

TEST_CASE(
    "On a refined layout the hemicube's item resolution is planned from the base cells, a disc map's from the finest",
    "[cpu][adaptive]") {
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 2);
  REQUIRE(tree.split(0));
  REQUIRE(tree.split(tree.nodes()[0].firstChild));  // cells of kTexel / 4 there
  const RefinedLayout refined = refineLayout(scene, tree);
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  auto resolution = [&](const Scene& s, const Atlas& a, Projection p) {
    return planShooting(s, a, kAutoShootLevel, kAutoItemResolution, p).itemResolution;
  };
  // 4 pixels an element across the 4-wide scene: 256 at kTexel, 1024 at a quarter of it; the
  // hemicube a quarter of that, at least 128.
  CHECK(resolution(scene, base, Projection::Orthographic) == 256);
  CHECK(resolution(refined.scene, atlas, Projection::Orthographic) == 1024);
  CHECK(resolution(scene, base, Projection::Hemicube) == 128);
  CHECK(resolution(refined.scene, atlas, Projection::Hemicube) == 128);  // occluders did not shrink (finest: 256)
}

TEST_CASE("A refined layout's item buffers draw each cut polygon whole, and see what its parts would show",
          "[gl][adaptive][heavy]") {  // the refined layout runs under ASan in its closed box (14 s there)
  const Scene scene = shadowScene();
  const Atlas base = buildAtlas(scene, kTexel);
  LeafTree tree(base, 2);
  for (int tile = 5; tile <= 10; tile += 5) REQUIRE(tree.split(tile));  // two floor tiles under the blocker's shadow
  REQUIRE(tree.split(tree.nodes()[5].firstChild));
  const RefinedLayout refined = refineLayout(scene, tree);
  REQUIRE(refined.scene.wholes.size() == 1);  // the floor, cut into parts
  CHECK(refined.scene.polygons().size() > scene.polygons().size());
  CHECK(itemTriangleCount(refined.scene, 0) == itemTriangleCount(scene, 0));  // the floor drawn once, whole
  double parts = 0;
  for (std::size_t p = 0; p < refined.scene.polygons().size(); ++p)
    if (refined.scene.wholeOf[p] >= 0) parts += refined.scene.polygons()[p].area;
  CHECK(parts == Approx(refined.scene.wholes[0].area).epsilon(1e-12));

  // The same layout with its parts drawn instead (no wholes): the same light on every object.
  Scene drawnInParts = refined.scene;
  drawnInParts.wholes.clear(), drawnInParts.wholeOf.clear();
  const Atlas atlas = buildAtlas(refined.scene, refined.specs, base.texelSize);
  ProgressiveSettings settings;
  settings.stop.targetConvergence = 0.99;
  auto solved = [&](const Scene& s) {
    test::backend();
    SolverState state(s, atlas);
    ProgressiveSolver solver(state, settings);
    advanceToStop(solver, {});
    return objectRadiosity(s, atlas, state.readRadiosity());
  };
  const auto whole = solved(refined.scene), inParts = solved(drawnInParts);
  REQUIRE(whole.size() == inParts.size());
  for (std::size_t o = 0; o < whole.size(); ++o) {
    CAPTURE(whole[o].name);
    CHECK(luminance(glm::dvec3(whole[o].mean)) ==
          Approx(luminance(glm::dvec3(inParts[o].mean))).epsilon(1e-6).margin(1e-9));
  }
}
