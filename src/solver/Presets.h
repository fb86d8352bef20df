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
  double refineNear;    // a receiver nearer a shooter than this many times its side sees it part by part (0:
                        // off); kAutoRefineNear: refineNearFor's choice from the stop rule
  bool operator==(const ItemPlan&) const = default;
};

struct Preset {
  std::string_view name;
  ItemPlan plan;
  std::string_view about;     // what it is for
  std::string_view measured;  // its speed and accuracy on the Cornell box (docs/cli.md)
};

inline constexpr double kAutoRefineNear = -1.0;  // ItemPlan::refineNear: refineNearFor decides
// The exact fast plan: hemicube item buffers at item-mesh level 0 (straight edges, so exact),
// planned shooter blocks and resolution, refined near its shooters where the stop rule asks for
// the accuracy that refinement gives (refineNearFor).
inline constexpr ItemPlan kFastPlan{Projection::Hemicube, 0, kAutoItemResolution, kAutoShootLevel, kAutoRefineNear};
// The fast plan with near-shooter refinement (visibility and transfer, conserving) within 4 block
// sides at any convergence: every Cornell object within 0.2 % of element-by-element shooting.
inline constexpr ItemPlan kRefinedPlan{Projection::Hemicube, 0, kAutoItemResolution, kAutoShootLevel, 4.0};
// Seed 003's configuration, the default until issue 30: orthographic hemisphere, L3, 512^2, level 1.
inline constexpr ItemPlan kSeed003Plan{Projection::Orthographic, 3, 512, 1, 0.0};
// Element-by-element shooting with a large exact item buffer: the reference the others are measured against.
inline constexpr ItemPlan kReferencePlan{Projection::Hemicube, 0, 1024, 0, 0.0};

inline constexpr std::string_view kDefaultPreset = "fast";

// --refine-near auto: near-shooter refinement where a solve stops at convergence kRefineFrom or
// more, else none. Unrefined, a coarse block's near receivers are off by up to ~1 % of their light
// (Cornell box, 2,508 elements: short block -1.03 % at 0.999); a solve stopped with more than 1 %
// of its light unshot is off by far more (at 0.9 every object is 9-14 % low, refined or not, the
// two within 0.5 %), so refining it buys nothing and costs 3x (H200) to 6x (llvmpipe) a shot. At
// 0.99 refinement takes the short block from -2.05 to -1.28 %, at 0.999 from -1.03 to -0.17 %
// (docs/design.md#near-shooter-refinement). Hierarchical radiosity likewise refines links only
// while their error is above the solution's tolerance.
inline constexpr double kRefineFrom = 0.99;
// --refine-near auto under the camera's --final-gather near: the gather regathers each pixel's near
// field from the elements, so what the solve got wrong at them beside contacts shows in the image.
// Refining within 16 block sides took the Cornell box's floor p95 4.13 -> 2.89 % and its
// interiors 0.68 -> 0.54 % (10k elements, 0.999, H200: run 2.1 -> 2.5 s; llvmpipe's solve 12 ->
// 96 s; docs/adaptive.md#the-solves-shooting-plan-near-contacts-2026-12-06-h200).
inline constexpr double kGatherRefineNear = 16.0;
// Camera images (--out, --image, docs/solve.md#exact-images): quick (B looked up in the elements,
// kDefaultSupersample^2 samples a pixel) or exact, with every refinement issue 31 measured against
// the unbiased reference: contact cuts (--discontinuities), per-pixel direct light (--direct), the
// near final gather (--final-gather, with kGatherRefineNear) and kExactImagesSupersample^2 samples.
// Cornell box, 10k elements, 256^2, against 65,536 paths a pixel (H200): interiors 0.80 -> 0.54 %,
// 1-px edge band 4.05 -> 1.27 %, floor p95 8.11 -> 2.89 %; run 0.33 -> 2.5 s. On llvmpipe the
// exact image costs 10-100x (the gather and per-pixel visibility on 2 cores), so auto takes it
// where a solve asks for a converged answer on a GPU. Each of those flags given overrides its part.
enum class ImagePlan { Auto, Quick, Exact };
inline constexpr double kExactImagesFrom = 0.999;
inline constexpr int kExactImagesSupersample = 4;
inline constexpr int kDefaultSupersample = 2;
inline constexpr int kAutoSupersample = 0;  // --supersample auto: as the image plan says
// Whether the camera image is exact: `plan` exact, or auto where one solve's image (`image`: --out
// or --image, no walkthrough) stops at targetConvergence >= kExactImagesFrom on a GPU (`gpu`).
bool exactImagesFor(ImagePlan plan, double targetConvergence, bool image, bool gpu);

// refineNear as given, or for auto where targetConvergence >= kRefineFrom: kGatherRefineNear for
// a solve whose images gather their near field, else kRefinedPlan's; below it 0.
double refineNearFor(double refineNear, double targetConvergence, bool nearGather);
std::string refineNearText(double refineNear);  // "auto" or the number
// --item-res's or --shoot-level's value as printed: "auto" for its auto value, else the number
// and `suffix` (a side in pixels: "^2").
std::string settingText(int value, int autoValue, const char* suffix = "");

const std::vector<Preset>& presets();  // `fast` (the default) first
// The preset of that name; InputError naming the presets otherwise.
const Preset& findPreset(std::string_view name);
// "--hemisphere hemicube --item-subdiv 0 --item-res auto --shoot-level auto --refine-near auto": the flags a plan sets.
std::string presetFlags(const ItemPlan& plan);
// "fast, seed003, reference", for messages.
std::string presetNames();
// What a run used, named: `chosen` alone when `actual` is its plan, else with the flags that
// overrode it ("seed003 with --item-res 256").
std::string presetLabel(std::string_view chosen, const ItemPlan& actual);

}  // namespace hemirad
