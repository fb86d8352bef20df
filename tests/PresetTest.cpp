// Presets (issue 30, src/solver/Presets.h): the default is the exact fast plan, `--preset seed003`
// is the old default bit for bit, flags beside a preset override it, and the report names it.
#include <fmt/format.h>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "gl/Backend.h"
#include "src/solver/Presets.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

const std::string kPresetScene = test::sourcePath("scenes/cornell/cornell.obj");

// `hemirad solve` of the Cornell box (or `scene`) with `flags`; its report.
nlohmann::json presetSolve(const std::string& flags, const std::string& scene = kPresetScene) {
  const std::string report = test::tempPath("preset" + std::to_string(std::hash<std::string>{}(flags)) + ".json");
  test::Run run = test::hemirad("solve " + scene + " --quiet " + flags + " --report " + report);
  INFO("solve " << flags << "\n" << run.output);
  REQUIRE(run.exitCode == 0);
  return test::readJson(report);
}

double jsonLuminance(const nlohmann::json& rgb) {
  return 0.2126 * rgb[0].get<double>() + 0.7152 * rgb[1].get<double>() + 0.0722 * rgb[2].get<double>();
}

// The largest relative difference of an object's mean luminance (the light's aside) between two
// reports of the same scene; each object's is logged.
double worstObject(const nlohmann::json& solved, const nlohmann::json& reference) {
  double worst = 0;
  for (const auto& f : solved["objects"])
    for (const auto& r : reference["objects"])
      if (f["name"] == r["name"] && f["name"] != "light") {
        const double a = jsonLuminance(f["mean_radiosity"]), b = jsonLuminance(r["mean_radiosity"]);
        UNSCOPED_INFO(solved["preset"].get<std::string>()
                      << " " << f["name"].get<std::string>() << ": " << a << ", element by element " << b << " ("
                      << (a / b - 1) * 100 << " %)");
        worst = std::max(worst, std::abs(a / b - 1));
      }
  return worst;
}

}  // namespace

TEST_CASE(
    "The default solve is the fast plan, refined near its shooters at 0.999, and every Cornell object is within "
    "0.2 % of element-by-element shooting there, unrefined within 1.2 %",
    "[heavy][cli][preset]") {
  // Cornell box, 2,500 elements, all solved to convergence 0.999 (so all leave the same unshot
  // share). Unrefined, the fast plan takes each coarse block's visibility from one origin and its
  // mean light, which is wrong for receivers close to it (issue 30). Measured here (llvmpipe):
  // default short block -0.17 %, tall block -0.09 %, the rest within 0.06 %; unrefined (--refine-near
  // 0) -1.03 % and -0.54 %; 1,056 shots against 11,472. Element by element: the reference preset,
  // its hemicube at 256^2 (exact: CGAL agreement 1.00000 at 10k elements,
  // docs/design.md#item-buffer-projection).
  const std::string common = "--elements 2500 --converge 0.999";
  const nlohmann::json fast = presetSolve(common), unrefined = presetSolve(common + " --refine-near 0"),
                       reference = presetSolve(common + " --preset reference --item-res 256");
  CHECK(fast["preset"] == "fast");
  CHECK(fast["projection"] == "hemicube");
  CHECK(fast["item_subdivision"] == 0);
  CHECK(fast["shoot_level"] == kAutoShootLevel);
  CHECK(fast["refine_near"] == kRefinedPlan.refineNear);  // auto, at 0.999
  CHECK(unrefined["preset"] == "fast with --refine-near 0");
  CHECK(reference["preset"] == "reference with --item-res 256");
  CHECK(reference["shoot_level"] == 0);
  CHECK(fast["shots"].get<unsigned>() * 2 < reference["shots"].get<unsigned>());  // coarse shooters: far fewer shots
  const double fastWorst = worstObject(fast, reference), unrefinedWorst = worstObject(unrefined, reference);
  INFO("worst object: default " << fastWorst * 100 << " %, unrefined " << unrefinedWorst * 100 << " % (default "
                                << fast["shots"] << " shots, element by element " << reference["shots"] << ")");
  CHECK(fastWorst < 0.002);
  CHECK(unrefinedWorst < 0.012);
  CHECK(unrefinedWorst > 2 * fastWorst);  // refinement is what brings it within 0.2 %
}

// --refine-near auto (src/solver/Presets.h refineNearFor): refined as the refined preset where the
// solve stops at kRefineFrom or more, unrefined below, where the unshot light outweighs what
// refinement corrects; the report gives the value the solve ran with.
TEST_CASE("The default refines near its shooters where the solve stops at 0.99 or more, as the refined preset does",
          "[cli][preset][heavy]") {  // bits of repeated solves: 16 s under ASan
  // Blocks of 4 x 4 given: at 600 elements auto would shoot element by element (too few a block,
  // ShootingPlan.cpp), where refining changes nothing.
  const std::string common = "--elements 600 --item-res 64 --shoot-level 2";
  const nlohmann::json below = presetSolve(common + " --converge 0.98"),
                       unrefined = presetSolve(common + " --converge 0.98 --refine-near 0"),
                       at = presetSolve(common + " --converge 0.99"),
                       refined = presetSolve(common + " --converge 0.99 --preset refined"),
                       off = presetSolve(common + " --converge 0.99 --refine-near 0");
  CHECK(below["refine_near"] == 0.0);
  CHECK(below["radiosity_hash"] == unrefined["radiosity_hash"]);
  CHECK(at["refine_near"] == kRefinedPlan.refineNear);
  CHECK(at["shooters_per_pass"] == 16);                              // refined within 4 sides: the whole batch
  CHECK(at["preset"] == "fast with --item-res 64 --shoot-level 2");  // auto is the preset's own value
  CHECK(at["radiosity_hash"] == refined["radiosity_hash"]);
  CHECK(at["radiosity_hash"] != off["radiosity_hash"]);  // the refinement changed something
}

// Auto's refined blocks pay where each holds many elements (kMinElementsPerBlock, ShootingPlan.cpp):
// the Cornell box at 600 elements would hold about 3 a block, so a solve refined within 4 sides
// shoots every element, and refinement, which has no parts to visit, changes nothing; at 2,500 its
// blocks hold 13 and stay, and at 600 an unrefined solve or one refined within 16 sides keeps them.
TEST_CASE(
    "Auto's shooter blocks stay where they hold 6 elements or more each or the solve refines none or 8 sides or "
    "more, and else every element shoots",
    "[cli][preset][heavy]") {                                              // bits of repeated solves: 17 s under ASan
  const std::string few = "--elements 600 --item-res 64 --converge 0.99";  // refined from 0.99 (auto)
  const nlohmann::json planned = presetSolve(few), single = presetSolve(few + " --shoot-level 0 --refine-near 0"),
                       many = presetSolve("--elements 2500 --converge 0.99 --shots 1"),
                       wide = presetSolve(few + " --refine-near 16 --shots 1"),
                       unrefined = presetSolve("--elements 600 --item-res 64 --shots 1");  // to 0.9
  CHECK(planned["shooter_blocks"] == planned["elements"]);
  CHECK(planned["refine_near"] == kRefinedPlan.refineNear);  // with nothing to refine
  CHECK(planned["radiosity_hash"] == single["radiosity_hash"]);
  CHECK(many["shooter_blocks"].get<double>() * 6 <= many["elements"].get<double>());
  CHECK(unrefined["refine_near"] == 0.0);
  CHECK(unrefined["shooter_blocks"].get<double>() * 2 < unrefined["elements"].get<double>());  // cheap blocks
  CHECK(wide["shooter_blocks"] == unrefined["shooter_blocks"]);  // within 16 sides small blocks shoot as elements
  CHECK(many["shooter_blocks"].get<double>() > 1);
}

// Under --final-gather near the camera regathers each pixel's near field from the elements, so auto
// refines within kGatherRefineNear block sides: the same solve as that value given, bit for bit.
TEST_CASE("Under the near gather the default refines within 16 block sides where the solve stops at 0.99 or more",
          "[cli][preset][heavy]") {  // bits of repeated solves: 15 s under ASan
  const std::string common = "--elements 600 --item-res 64 --width 16 --height 16 --out " +
                             test::tempPath("gather_plan.exr"),
                    gather = " --direct per-pixel --final-gather near";
  const nlohmann::json at = presetSolve(common + " --converge 0.99" + gather),
                       given = presetSolve(common + " --converge 0.99 --refine-near 16"),
                       below = presetSolve(common + " --converge 0.98" + gather);
  CHECK(at["refine_near"] == kGatherRefineNear);
  CHECK(at["shooters_per_pass"] == 16);
  CHECK(at["preset"] == "fast with --item-res 64");
  CHECK(at["radiosity_hash"] == given["radiosity_hash"]);
  CHECK(below["refine_near"] == 0.0);
}

// Refined within 16 sides, a receiver near all 16 shooters of a pass walks 16 shooters' parts; in
// one invocation that passed llvmpipe's 65,535 loop turns (shaders/bvh.glsl) and its last walks
// ended early: the floor -0.73 %, the short block -0.52 % (llvmpipe, 8 x 8-texel blocks). The near
// pairs now run one shooter a dispatch (transfer_split.glsl): every object within 0.06 % of
// element-by-element shooting (--shoot-level 0, exact: tested above).
TEST_CASE(
    "Refined within 16 block sides at 16 shooters a pass, every Cornell object is within 0.25 % of "
    "element-by-element shooting",
    "[heavy][cli][preset]") {
  const std::string common = "--elements 2500 --converge 0.999 --discontinuities contact";
  const nlohmann::json wide = presetSolve(common + " --shoot-level 3 --refine-near 16 --shooters-per-pass 16"),
                       reference = presetSolve(common + " --shoot-level 0 --refine-near 0");
  CHECK(wide["shooters_per_pass"] == 16);
  CHECK(reference["shooters_per_pass"] == 16);
  CHECK(worstObject(wide, reference) < 0.0025);
}

// A concave bowl (a lower hemisphere of 24 x 6 quads, faces inward; curved charts of 30 degrees)
// lit from 6 radii above, so the scene is wide and auto's blocks large: its own interreflection is
// much of its light. A curved chart's block shoots from one eye with its facets' mean normal;
// from auto's blocks (a quarter of the scene wide: 16 x 16 texels, cut at the charts' edges) the
// bowl was 1.6 % dark in red (2.7 % in luminance) against element-by-element shooting (llvmpipe).
// Unrefined (--refine-near 0), as below 0.99: refined within 4 sides, 2 x 2 blocks hold too few
// elements and every element shoots (kMinElementsPerBlock), so there the plans would be the same.
TEST_CASE(
    "On curved charts the default plan shoots from 2 x 2 texels at most: a lit bowl's mean light is within 0.5 % of "
    "element-by-element shooting, from 8 x 8 texels over 1 % dark",
    "[heavy][cli][preset]") {
  std::string obj = "mtllib m.mtl\no bowl\nusemtl white\n" + test::uvSphereObj({0, 0, 0}, 1, 24, 12, 6, 1, true);
  obj += "o light\nusemtl light\nv -0.6 6 -0.6\nv 0.6 6 -0.6\nv 0.6 6 0.6\nv -0.6 6 0.6\nf 169 170 171 172\n";
  const std::string scene =
      test::writeScene("bowl", obj, "newmtl white\nKd 0.8 0.8 0.8\nnewmtl light\nKd 0 0 0\nKe 10 10 10\n");
  auto solve = [&](const std::string& plan) {  // the bowl's mean B (red), the report's shooter blocks
    const nlohmann::json json =
        presetSolve("--elements 1000 --converge 0.999 --ambient off --refine-near 0" + plan, scene);
    return std::pair(test::reportObjectB(json, "bowl"), json["shooter_blocks"].get<int>());
  };
  const auto [planned, blocks] = solve("");
  const auto [exact, elements] = solve(" --shoot-level 0");
  const auto [coarse, coarseBlocks] = solve(" --shoot-level 3");
  INFO("default " << planned << " from " << blocks << " blocks, element by element " << exact << " from " << elements
                  << ", 8 x 8 texels " << coarse << " from " << coarseBlocks);
  CHECK(blocks < elements / 3);                  // measured 240 of 983: 2 x 2 texels, some cut
  CHECK(std::abs(planned / exact - 1) < 0.005);  // measured -0.11 %
  CHECK(coarse / exact - 1 < -0.01);             // measured -1.62 %: the cap is what keeps the light
}

// The image plan (docs/solve.md#exact-images): auto is exact where one solve's image stops at
// kExactImagesFrom or more on a GPU, quick on a CPU rasterizer and below it.
TEST_CASE(
    "The auto image plan is exact for a converged solve's image on a GPU, quick on a CPU, below 0.999 or "
    "without an image",
    "[preset]") {
  CHECK(exactImagesFor(ImagePlan::Auto, 0.999, true, true));
  CHECK(exactImagesFor(ImagePlan::Auto, 0.9999, true, true));
  CHECK_FALSE(exactImagesFor(ImagePlan::Auto, 0.999, true, false));   // llvmpipe: 10-100x the time
  CHECK_FALSE(exactImagesFor(ImagePlan::Auto, 0.998, true, true));    // not converged enough to show
  CHECK_FALSE(exactImagesFor(ImagePlan::Auto, 0.999, false, true));   // no --out or --image
  CHECK(exactImagesFor(ImagePlan::Exact, 0.5, false, false));         // asked for: always
  CHECK_FALSE(exactImagesFor(ImagePlan::Quick, 0.9999, true, true));  // asked against: never
  // What `gpu` is told from: osmesa is llvmpipe, and an EGL device that is not listed is no GPU.
  CHECK(gl::rendersOnCpu({gl::BackendKind::OSMesa, -1, false}));
  CHECK(gl::rendersOnCpu({gl::BackendKind::Egl, 99, false}));
}

// --image-plan exact (auto's choice on a GPU, tested above; CI has llvmpipe): contact cuts,
// per-pixel direct light, the near gather (so refined within 16 sides) and 4 x 4 samples, bit for
// bit the image those flags give; each flag given keeps its value; auto on llvmpipe is quick and
// says how to ask for the exact image.
TEST_CASE(
    "The exact image plan is bit for bit the image of its four refinements given, a flag given beside it keeps its "
    "value, and on llvmpipe auto is the quick image",
    "[cli][preset][heavy]") {
  const std::string common = "--elements 300 --item-res 64 --width 16 --height 16 --converge 0.999 --out ";
  const std::string a = test::tempPath("exact_plan.exr"), b = test::tempPath("exact_given.exr"),
                    c = test::tempPath("exact_quick.exr");
  const nlohmann::json exact = presetSolve(common + a + " --image-plan exact"),
                       given = presetSolve(common + b +
                                           " --discontinuities contact --direct per-pixel --final-gather near "
                                           "--refine-near 16 --supersample 4"),
                       overridden = presetSolve(common + c + " --image-plan exact --direct atlas --supersample 3"),
                       quick = presetSolve(common + c);
  CHECK(exact["discontinuities"] == "contact");
  CHECK(exact["direct"] == "per-pixel");
  CHECK(exact["final_gather"] == "near");
  CHECK(exact["refine_near"] == kGatherRefineNear);
  CHECK(exact["camera_image"]["supersample"] == kExactImagesSupersample);
  CHECK(exact["elements"] > quick["elements"]);  // the contact cuts' pieces
  CHECK(exact["radiosity_hash"] == given["radiosity_hash"]);
  CHECK(!test::readText(a).empty());
  CHECK(test::readText(a) == test::readText(b));
  CHECK(overridden["discontinuities"] == "contact");
  CHECK(overridden["direct"] == "atlas");                       // given
  CHECK_FALSE(overridden.contains("final_gather"));             // auto: no gather without per-pixel light
  CHECK(overridden["refine_near"] == kRefinedPlan.refineNear);  // so auto's 4
  CHECK(overridden["camera_image"]["supersample"] == 3);        // given
  CHECK(quick["discontinuities"] == "off");
  CHECK(quick["direct"] == "atlas");
  CHECK(quick["camera_image"]["supersample"] == kDefaultSupersample);
  const test::Run run = test::hemirad("solve " + kPresetScene + " " + common + c + " --quiet");
  CHECK_THAT(run.output, Contains("on a CPU rasterizer: the quick camera image; --image-plan exact for the exact one"));
  // The exact image's line names what is in effect of it: not the direct light given as atlas.
  const test::Run told = test::hemirad("solve " + kPresetScene + " " + common + c +
                                       " --quiet --image-plan exact --direct atlas --supersample 3");
  CHECK_THAT(told.output,
             Contains("the camera image is exact (--image-plan exact): contact cuts, 3 x 3 samples a pixel"));
}

TEST_CASE("The seed003 preset reproduces the old default bitwise: seed 003's item buffer and level-1 shooting",
          "[heavy][cli][preset]") {  // CLI runs without memory-safety stakes: optimized only
  const std::string common = "--elements 1500 --shots 64";
  const nlohmann::json preset = presetSolve(common + " --preset seed003");
  const nlohmann::json explicitFlags =
      presetSolve(common + " --hemisphere orthographic --item-subdiv 3 --item-res 512 --shoot-level 1");
  CHECK(preset["radiosity_hash"] == explicitFlags["radiosity_hash"]);
  CHECK(preset["preset"] == "seed003");
  CHECK(explicitFlags["preset"] ==
        "fast with --hemisphere orthographic --item-subdiv 3 --item-res 512 --shoot-level 1");
  for (const char* field : {"projection", "item_subdivision", "item_resolution", "shoot_level", "item_triangles"})
    CHECK(preset[field] == explicitFlags[field]);
  CHECK(preset["projection"] == "orthographic");
  CHECK(preset["item_resolution"] == 512);
  const nlohmann::json byDefault = presetSolve(common);
  CHECK(byDefault["radiosity_hash"] != preset["radiosity_hash"]);  // the default changed: the fast plan
  CHECK(byDefault["preset"] == "fast");
}

TEST_CASE("Explicit flags override a preset, given before or after it, and the report names what was overridden",
          "[heavy][cli][preset]") {
  const std::string common = "--elements 1500 --shots 32";
  const nlohmann::json after = presetSolve(common + " --preset seed003 --item-res 256 --shoot-level 2");
  const nlohmann::json before = presetSolve(common + " --item-res 256 --shoot-level 2 --preset seed003");
  const nlohmann::json plain =
      presetSolve(common + " --hemisphere orthographic --item-subdiv 3 --item-res 256 --shoot-level 2");
  CHECK(after["item_resolution"] == 256);
  CHECK(after["shoot_level"] == 2);
  CHECK(after["item_subdivision"] == 3);  // the preset's
  CHECK(after["projection"] == "orthographic");
  CHECK(after["preset"] == "seed003 with --item-res 256 --shoot-level 2");
  CHECK(before["preset"] == after["preset"]);
  CHECK(before["radiosity_hash"] == after["radiosity_hash"]);
  CHECK(plain["radiosity_hash"] == after["radiosity_hash"]);

  // bench: the same rule, and its JSON names the preset.
  const std::string json = test::tempPath("preset-bench.json");
  test::Run bench = test::hemirad("bench --scenes " + test::sourcePath("scenes/analytic/parallel_squares.obj") +
                                  " --elements 200 --split-shots 4 --item-subdiv 1 --preset seed003 --json " + json);
  INFO(bench.output);
  REQUIRE(bench.exitCode == 0);
  const nlohmann::json b = test::readJson(json);
  CHECK(b["preset"] == "seed003 with --item-subdiv 1");
  CHECK(b["item_subdivision"] == 1);
  CHECK(b["item_resolution"] == 512);
  CHECK(b["projection"] == "orthographic");
  CHECK_THAT(bench.output, Contains("preset seed003 with --item-subdiv 1"));
}

TEST_CASE(
    "Every command that solves by progressive refinement takes --preset, and without it shows the fast plan as "
    "its default",
    "[heavy][cli][preset]") {
  for (const char* command : {"solve", "bench", "view", "experiment", "compare-methods"}) {
    test::Run help = test::hemirad(std::string(command) + " --help");
    INFO(command << "\n" << help.output);
    CHECK(help.exitCode == 0);
    CHECK_THAT(help.output, Contains("--preset"));
    CHECK_THAT(help.output, Contains("fast|refined|seed003|reference"));
  }
  for (const char* command : {"solve", "bench", "view"}) {
    test::Run help = test::hemirad(std::string(command) + " --help");
    CHECK_THAT(help.output, Contains("hemicube (preset fast)"));
    CHECK_THAT(help.output, Contains("auto (preset fast)"));
  }
}
