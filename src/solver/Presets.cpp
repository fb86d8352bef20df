#include "src/solver/Presets.h"

#include <fmt/format.h>

#include "src/base/Error.h"

namespace hemirad {

std::string settingText(int value, int autoValue, const char* suffix) {
  return value == autoValue ? "auto" : std::to_string(value) + suffix;
}

const std::vector<Preset>& presets() {
  // `measured`: Cornell box (scenes/cornell), OSMesa/llvmpipe on 2 loaded shared cores, 2026-12-03:
  // time to 90 % at 9,992 elements (bench, one preset after another); objects' mean luminance at
  // convergence 0.999 at 2,508 elements against element-by-element shooting (`reference` at 256^2),
  // as tests/PresetTest.cpp measures it. src/options/CliDocs.cpp prints them into docs/cli.md.
  static const std::vector<Preset> table{
      {"fast", kFastPlan,
       "the default: exact hemicube item buffers (straight edges at item-mesh level 0), shooter blocks and item "
       "resolution planned from the scene",
       "272 shots, 4.4 s to 90 % (unrefined there); at 0.999 (refined: --refine-near auto), 1,056 shots in 2.4 s "
       "(unrefined 0.75 s, the reference 11.3 s; 2026-12-05), objects within 0.17 % (short block -0.17 %, tall block "
       "-0.09 %; unrefined -1.03 % and -0.54 %)"},
      {"refined", kRefinedPlan,
       "the fast plan refined near its shooters at any convergence (--refine-near 4; the default refines from 0.99): "
       "each receiver within 4 block sides gets the block's parts' own light, seen from their own origins, the far "
       "ones the rest, conserving the shot",
       "at 0.999 and 2,508 elements, 1,056 shots in 3.8 s (5.2x fast's 0.73 s; the reference's 11.6 s), objects "
       "within 0.17 % (short block -0.17 %, tall block -0.09 %); H200 to 90 %: 49 ms at 10k, 71 ms at 100k, 172 ms "
       "at 1M elements (fast: 15, 25, 62)"},
      {"seed003", kSeed003Plan,
       "seed 003's configuration and the default before issue 30, bitwise: the orthographic hemisphere; the artifact "
       "studies are about it",
       "2,432 shots, 195 s to 90 % (45x fast's); at 0.999, 3,014 shots, objects within 0.65 % (floor +0.65 %, "
       "back wall +0.19 %, the rest within 0.17 %)"},
      {"reference", kReferencePlan,
       "element-by-element shooting with large exact item buffers: what the others are measured against",
       "9,408 shots, 588 s to 90 % (134x fast's; the load was higher by then); at 0.999 (at 256^2), 11,472 shots: "
       "the reference"},
  };
  return table;
}

std::string presetFlags(const ItemPlan& plan) {
  return fmt::format("--hemisphere {} --item-subdiv {} --item-res {} --shoot-level {} --refine-near {}",
                     projectionName(plan.projection), plan.itemSubdivision,
                     settingText(plan.itemResolution, kAutoItemResolution),
                     settingText(plan.shootLevel, kAutoShootLevel), refineNearText(plan.refineNear));
}

std::string refineNearText(double refineNear) {
  return refineNear == kAutoRefineNear ? "auto" : fmt::format("{:g}", refineNear);
}

double refineNearFor(double refineNear, double targetConvergence, bool nearGather) {
  if (refineNear != kAutoRefineNear) return refineNear;
  if (targetConvergence < kRefineFrom) return 0.0;
  return nearGather ? kGatherRefineNear : kRefinedPlan.refineNear;
}

bool exactImagesFor(ImagePlan plan, double targetConvergence, bool image, bool gpu) {
  if (plan != ImagePlan::Auto) return plan == ImagePlan::Exact;
  return image && gpu && targetConvergence >= kExactImagesFrom;
}

std::string presetNames() {
  std::string names;
  for (const Preset& p : presets()) names += (names.empty() ? "" : ", ") + std::string(p.name);
  return names;
}

const Preset& findPreset(std::string_view name) {
  for (const Preset& p : presets())
    if (p.name == name) return p;
  throw InputError(fmt::format("--preset {}: not a preset; the presets are {} (the default: {})", name, presetNames(),
                               kDefaultPreset));
}

std::string presetLabel(std::string_view chosen, const ItemPlan& actual) {
  const ItemPlan& plan = findPreset(chosen).plan;
  std::string label(chosen), with;
  auto differs = [&with](bool differ, const std::string& flag) {
    if (differ) with += (with.empty() ? " with " : " ") + flag;
  };
  differs(actual.projection != plan.projection, "--hemisphere " + projectionName(actual.projection));
  differs(actual.itemSubdivision != plan.itemSubdivision, fmt::format("--item-subdiv {}", actual.itemSubdivision));
  differs(actual.itemResolution != plan.itemResolution,
          "--item-res " + settingText(actual.itemResolution, kAutoItemResolution));
  differs(actual.shootLevel != plan.shootLevel, "--shoot-level " + settingText(actual.shootLevel, kAutoShootLevel));
  differs(actual.refineNear != plan.refineNear, "--refine-near " + refineNearText(actual.refineNear));
  return label + with;
}

}  // namespace hemirad
