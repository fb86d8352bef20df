// The item-buffer plans a progressive solve can start from, defined once (issue 30): the item
// buffer's projection, item-mesh level and resolution, and the shooters' block level. The first,
// `fast`, is every command's default (ProgressiveSettings' initial values); `--preset NAME` starts
// from another, and flags given beside it override its values one by one. docs/cli.md lists them
// with their measured speed and accuracy (src/options/CliDocs.cpp prints `measured`).
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "src/solver/Projection.h"
#include "src/solver/ShootingPlan.h"

namespace hemirad {

struct ItemPlan {
  Projection projection;
  int itemSubdivision;  // item-mesh 1-to-4 splits
  int itemResolution;   // pixels a side; kAutoItemResolution: planned from the element size
  int shootLevel;       // 2^k x 2^k texel shooter blocks; kAutoShootLevel: planned from the scene
  double refineNear;    // a receiver nearer a shooter than this many times its side sees it part by part (0: off)
  bool operator==(const ItemPlan&) const = default;
};

struct Preset {
  std::string_view name;
  ItemPlan plan;
  std::string_view about;     // what it is for
  std::string_view measured;  // its speed and accuracy on the Cornell box (docs/cli.md)
};

// The exact fast plan: hemicube item buffers at item-mesh level 0 (straight edges, so exact),
// planned shooter blocks and resolution. Near-shooter refinement (--refine-near) is not in it: it
// costs 2-3x the time on the H200 (docs/design.md#near-shooter-refinement).
inline constexpr ItemPlan kFastPlan{Projection::Hemicube, 0, kAutoItemResolution, kAutoShootLevel, 0.0};
// The fast plan with near-shooter refinement (visibility and transfer, conserving) within 4 block
// sides: every Cornell object within 0.2 % of element-by-element shooting.
inline constexpr ItemPlan kRefinedPlan{Projection::Hemicube, 0, kAutoItemResolution, kAutoShootLevel, 4.0};
// Seed 003's configuration, the default until issue 30: orthographic hemisphere, L3, 512^2, level 1.
inline constexpr ItemPlan kSeed003Plan{Projection::Orthographic, 3, 512, 1, 0.0};
// Element-by-element shooting with a large exact item buffer: the reference the others are measured against.
inline constexpr ItemPlan kReferencePlan{Projection::Hemicube, 0, 1024, 0, 0.0};

inline constexpr std::string_view kDefaultPreset = "fast";

const std::vector<Preset>& presets();  // `fast` (the default) first
// The preset of that name; InputError naming the presets otherwise.
const Preset& findPreset(std::string_view name);
// "--hemisphere hemicube --item-subdiv 0 --item-res auto --shoot-level auto --refine-near 0": the flags a plan sets.
std::string presetFlags(const ItemPlan& plan);
// "fast, seed003, reference", for messages.
std::string presetNames();
// What a run used, named: `chosen` alone when `actual` is its plan, else with the flags that
// overrode it ("seed003 with --item-res 256").
std::string presetLabel(std::string_view chosen, const ItemPlan& actual);

}  // namespace hemirad
