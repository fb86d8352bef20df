#include "src/options/Options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>

#include "gl/Backend.h"
#include "src/base/DataDir.h"
#include "src/base/Error.h"
#include "src/reference/PathTracer.h"
#include "src/scene/Charts.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Control.h"
#include "src/solver/Presets.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/Projection.h"
#include "src/solver/ShootingPlan.h"
#include "src/solver/Solver.h"

namespace hemirad::options {

namespace {

// A number parsed whole (no trailing text), finite, passing `ok`.
CLI::Validator number(bool (*ok)(double), const std::string& description, const std::string& error) {
  return CLI::Validator(
      [ok, error](std::string& v) {
        char* end = nullptr;
        double x = std::strtod(v.c_str(), &end);
        return end != v.c_str() && *end == '\0' && std::isfinite(x) && ok(x) ? std::string()
                                                                             : error + ", not '" + v + "'";
      },
      description);
}

template <class T>
CLI::Validator oneOf(const std::map<std::string, T>& names, const std::string& description) {
  return CLI::Validator(CLI::CheckedTransformer(names, CLI::ignore_case)).description(description);
}

CLI::Validator names(const std::vector<std::string>& names) {
  return CLI::Validator(CLI::IsMember(names)).description(fmt::format("{}", fmt::join(names, "|")));
}

// One of `names`, stored as its enumerator's number: what CLI11 reads into a bound enumeration.
template <class T>
CLI::Validator enumeration(const std::vector<std::pair<std::string, T>>& names) {
  std::vector<std::string> listed;
  for (const auto& [name, value] : names) listed.push_back(name);
  return CLI::Validator(
      [names, listed](std::string& v) {
        for (const auto& [name, value] : names)
          if (v == name) return v = std::to_string(int(value)), std::string();
        return fmt::format("{} not in {{{}}}", v, fmt::join(listed, ","));
      },
      fmt::format("{}", fmt::join(listed, "|")));
}

// --hemisphere: a canonical name or an alias (parseProjectionFlag warns for the old one), stored as
// the Projection's number, as CLI11 stores an enumeration into a bound field; validate's `all`
// as kAllProjections.
CLI::Validator projectionChoice() {
  std::vector<std::string> accepted = projectionNames();
  accepted.push_back("all");
  std::vector<std::string> canonical;
  for (Projection p : allProjections()) canonical.push_back(projectionName(p));
  return CLI::Validator(
      [accepted](std::string& v) {
        if (std::find(accepted.begin(), accepted.end(), v) == accepted.end())
          return fmt::format("{} not in {{{}}}", v, fmt::join(accepted, ","));
        v = std::to_string(v == "all" ? kAllProjections : int(parseProjectionFlag(v)));
        return std::string();
      },
      fmt::format("{}|all", fmt::join(canonical, "|")));
}

std::map<std::string, Algorithm> algorithms() {
  std::map<std::string, Algorithm> m;
  for (const std::string& name : algorithmNames()) m[name] = parseAlgorithm(name);
  return m;
}

const CLI::Validator kCount = CLI::Range(1u, 1u << 30);
const CLI::Validator kLevel = CLI::Range(0, 8);
const CLI::Validator kPixels = CLI::Range(1, 16384);

const CLI::Validator kNone;  // any value the field parses

// An existing file, or a relative path to one of the scenes shipped beside the binary
// (base/DataDir.h), which it becomes: bench and experiment run from any directory.
const CLI::Validator kScene(
    [](std::string& v) {
      v = findScene(v);
      return CLI::ExistingFile(v);
    },
    "FILE");

// "auto" (planned: src/solver/ShootingPlan.h, Presets.h; stored as autoValue) or a number from lo
// to hi: an integer unless `real`.
CLI::Validator autoOr(double autoValue, double lo, double hi, bool real = false) {
  const std::string range = fmt::format("{:g} to {:g}", lo, hi);
  return CLI::Validator(
      [=](std::string& v) {
        if (v == "auto") {
          v = fmt::format("{:g}", autoValue);
          return std::string();
        }
        char* end = nullptr;
        const double x = real ? std::strtod(v.c_str(), &end) : double(std::strtol(v.c_str(), &end, 10));
        return end != v.c_str() && *end == '\0' && x >= lo && x <= hi
                   ? std::string()
                   : fmt::format("must be auto or {} from {}, not '{}'", real ? "a number" : "an integer", range, v);
      },
      "auto or " + range);
}

// --preset: a name from the preset table (src/solver/Presets.h); the error names them all.
CLI::Validator presetChoice() {
  std::vector<std::string> listed;
  for (const Preset& p : presets()) listed.emplace_back(p.name);
  return CLI::Validator(
      [](std::string& v) {
        for (const Preset& p : presets())
          if (v == p.name) return std::string();
        return fmt::format("'{}' is not a preset; the presets are {} (the default: {})", v, presetNames(),
                           kDefaultPreset);
      },
      fmt::format("{}", fmt::join(listed, "|")));
}

std::vector<Flag> sceneAndSolverFlags() {
  const auto positive = number([](double x) { return x > 0; }, "> 0", "must be a positive number");
  const auto unit = number([](double x) { return x > 0 && x < 1; }, "in (0, 1)", "must be in (0, 1)");
  const CLI::Validator none = kNone;
  return {
      // The scene and its elements.
      {"--emission", "KEY", "MTL key that gives emission: ke or ka (the thesis)",
       oneOf(std::map<std::string, EmissionSource>{{"ke", EmissionSource::Ke}, {"ka", EmissionSource::Ka}}, "ke|ka"),
       "ke"},
      {"--texel-size", "SIZE", "Element (texel) side in scene units", positive.description("SIZE > 0")},
      {"--elements", "N", "Choose the texel size for about N elements",
       CLI::Range(std::size_t(1), std::size_t(1) << 28)},
      {"--chart-angle", "DEG",
       "Charts join connected polygons of one material and object whose normals lie within DEG degrees "
       "of the chart's first (0: coplanar ones only; 30: a curved surface's facets join, so its light shows no "
       "facets), "
       "projected onto one texel grid (docs/design.md#atlas-and-elements)",
       CLI::Range(0.0, 60.0)},
      {"--uv", "SOURCE",
       "Where charts' texel grids come from: auto (charts by --chart-angle; flat ones projected onto their plane, "
       "smooth curved surfaces of up to 90 degrees of normals unrolled by a conformal map, LSCM, where it is "
       "one-to-one and little distorted), projection (every chart projected along its first polygon's normal, "
       "curved ones within --chart-angle of it) or input (the scene's own lightmap UVs, glTF TEXCOORD_1 or an OBJ's "
       "vt: each UV island one chart, scaled so --elements and --texel-size hold)",
       oneOf(
           std::map<std::string, UvSource>{
               {"auto", UvSource::Auto}, {"input", UvSource::Input}, {"projection", UvSource::Projection}},
           "auto|projection|input"),
       "auto"},
      {"--subdivide", "MODE",
       "Elements: uniform (one texel size) or adaptive (seed 003's quadtree: solve, split the 16 x 16-texel leaves "
       "where the radiosity's relative change per texel exceeds --split-gradient into four of half the texel side, "
       "solve again, to --leaf-depth; --elements is the final count at most, the first round a quarter of it, the "
       "steepest leaves splitting first; docs/adaptive.md)",
       oneOf(std::map<std::string, bool>{{"uniform", false}, {"adaptive", true}}, "uniform|adaptive"), "uniform"},
      {"--discontinuities", "MODE",
       "Discontinuity meshing: contact cuts every planar chart along the outlines of polygons touching it (edges "
       "within 1e-3 of the scene's diagonal in front of its plane: a block on the floor, a lamp just under the "
       "ceiling), each side its own chart, so no element straddles lit and unlit parts; off: no cuts; auto: contact "
       "for an exact camera image (--image-plan), else off (docs/adaptive.md#discontinuity-meshing-d0)",
       names({"auto", "contact", "off"}), "auto"},
      {"--leaf-depth", "D", "Adaptive: the quadtree's maximum depth (texels 2^-D of --texel-size a side)",
       CLI::Range(1, 4)},
      {"--split-gradient", "G",
       "Adaptive: a texel is steep where its radiosity changes by more than G of itself per texel (central "
       "differences over its chart's neighbours); a leaf with 8 steep texels splits",
       positive},
      {"--scenes", "OBJ",
       "OBJ scenes; a relative path not found from here is read from the shipped scenes (docs/install.md)", kScene},
      // The solver.
      {"--method", "METHOD",
       "Radiosity method: progressive refinement; stochastic iteration (seed 000: --shots iterations of K random "
       "texel shooters, K = --shooters-per-pass); instant radiosity (seed 002: --vpls virtual point lights traced "
       "from the emitters, camera images only)",
       kNone, "progressive"},  // the commands check the names (src/method/Registry.h)
      {"--converge", "C", "Stop at this convergence, 1 - unshot/emitted power", unit},
      {"--shots", "N", "Stop after N shots", kCount, "no limit"},
      {"--item-subdiv", "L", "Item-mesh 1-to-4 subdivision level", kLevel},
      {"--item-res", "PIXELS|auto",
       "Item buffer resolution in pixels (the pixel budget's side), or auto: from the element size (the "
       "hemicube, which resolves occluders only, a quarter of that)",
       autoOr(kAutoItemResolution, 16, 16384)},
      {"--hemisphere", "NAME",
       "Item buffer: orthographic (seed 003's r = sin theta, the Nusselt analog; `stereographic` and `hemisphere` are "
       "its old names), hemicube (exact at --item-subdiv 0; equal pixel budgets), conformal (the true stereographic "
       "map r = tan theta/2, = `paraboloid`) or equal-area (Lambert); the disc maps' curved edges need --item-subdiv "
       "3-4; validate: a list, or all",
       projectionChoice()},
      {"--shoot-level", "K|auto",
       "Substructuring: shoot from 2^K x 2^K texel blocks, or auto: blocks about 1/4 of the "
       "scene wide (emitters 1/16; curved charts at most 2 x 2 texels), or single elements where such blocks would "
       "hold fewer than 6 each (few elements, or many small charts) in a solve refined within fewer than 8 sides",
       autoOr(kAutoShootLevel, 0, 8)},
      {"--refine-near", "K|auto",
       fmt::format(
           "A receiver nearer a shooter block than K times the block's side gets the block's quadrants' own light one "
           "by one, each from its own origin with exact visibility, and the far receivers what the near ones took "
           "less, so the shot is conserved (hierarchical radiosity's link refinement; 0: off; {0:g}: preset refined); "
           "auto: {0:g} where the solve stops at --converge {1:g} or more, whose accuracy needs it (every Cornell "
           "object within 0.2 % of element-by-element shooting at 0.999), {2:g} there under --final-gather near, "
           "whose images show the elements' errors beside contacts, else 0 "
           "(docs/design.md#near-shooter-refinement)",
           kRefinedPlan.refineNear, kRefineFrom, kGatherRefineNear),
       autoOr(kAutoRefineNear, 0, 16, true)},
      {"--visibility", "HOW",
       "Whether a receiver sees a shooter: item-buffer (seed 003: the shooter's item buffer nominates occluders, "
       "exact segment tests decide; an occluder thinner than a pixel can be missed), bvh (exact segment tests "
       "through the scene's BVH and no item buffer: nothing missed, and no shot draws the scene, which on "
       "scenes of many triangles is most of a shot) or auto (bvh where the scene has at least as many triangles "
       "as there are elements, furnished scenes, and no particular item buffer is asked for: the fast plan's "
       "projection, level and resolution; else item-buffer); validate: bvh adds the traced test as a "
       "configuration beside the item buffers; docs/design.md#visibility",
       enumeration<Visibility>({{visibilityName(Visibility::Auto), Visibility::Auto},
                                {visibilityName(Visibility::ItemBuffer), Visibility::ItemBuffer},
                                {visibilityName(Visibility::Bvh), Visibility::Bvh}}),
       "auto"},
      {"--direct", "MODE",
       "Camera images' direct light: looked up in the elements like the rest (atlas), or computed per pixel, exactly "
       "(per-pixel: Lambert's contour integral to each emitter with exact visibility, the solution giving only the "
       "indirect light; sharp shadow edges; docs/design.md#per-pixel-direct); auto: per-pixel for an exact camera "
       "image (--image-plan) or with --final-gather near, else atlas. The atlas, PLY and glTF keep B",
       names({"auto", "atlas", "per-pixel"}), "auto"},
      {"--final-gather", "MODE",
       "Camera images with per-pixel direct light: off, or near (each pixel gathers again the light of the elements "
       "within two of their sides, exactly, at its own point: creases and contacts that a lookup between element "
       "centres smooths over; docs/design.md#final-gather); auto: near for an exact camera image (--image-plan) "
       "with its direct light per pixel, else off",
       names({"auto", "off", "near"}), "auto"},
      {"--preset", "NAME",
       "Start the item buffer and shooters from a named plan (docs/cli.md#presets): fast (the default: hemicube at "
       "item-mesh level 0, planned shooter blocks and resolution), refined (fast, refined near its shooters: "
       "--refine-near 4), seed003 (seed 003's orthographic hemisphere, L3, 512^2, level-1 shooting: the default "
       "before issue 30, bitwise) or reference (element-by-element shooting, hemicube 1024^2); --hemisphere, "
       "--item-subdiv, --item-res, --shoot-level and --refine-near given beside it override its values",
       presetChoice(), std::string(kDefaultPreset)},
      {"--algorithm", "NAME",
       "Progressive shooter choice: progressive; importance: shooters ranked by unshot power x importance from "
       "the camera; perspective: importance-driven, and only what the view sees receives (seed 004)",
       oneOf(algorithms(), "progressive|importance|perspective"), "progressive"},
      {"--algorithms", "NAME", "Algorithms to compare", names(algorithmNames())},
      {"--fov-decay", "SHOTS",
       "Perspective-driven: shots over which the simulated field of view grows from the camera's to the whole "
       "scene after each camera move",
       kCount, "a quarter of the shooter blocks"},
      {"--shooters-per-pass", "K",
       fmt::format("Seed 003's batching: the K best blocks shoot in one pass; stochastic "
                   "iteration: K random texels an iteration (at most {})",
                   kMaxPassShooters),
       CLI::Range(1, int(kMaxPassShooters))},
      {"--seed", "N",
       "Random seed of stochastic iteration, instant radiosity and the path-traced reference: the "
       "same seed and backend give bitwise the same result",
       CLI::Range(0u, 0xFFFFFFFFu)},
      {"--transport", "WHAT",
       "Stochastic iteration: what the random operator carries each iteration, the last iterate (a chain, "
       "averaged) or the running mean itself (seed 000's eq. 2 as printed; slower to lose its bias)",
       names({"iterate", "mean"})},
      // Instant radiosity (seed 002, docs/instant.md).
      {"--vpls", "N", "Instant radiosity: virtual point lights, over all bounces (Keller's quasi-random walk)",
       CLI::Range(1u, 1u << 16)},
      {"--vpl-bounces", "D", "Instant radiosity: the deepest bounce that leaves a VPL (0: direct light only)",
       CLI::Range(0, 15)},
      {"--vpl-clamp", "F",
       "Instant radiosity: clamp cos cos / r^2 at 1 / (F x scene diagonal)^2 (the VPL singularity); 0: no clamp",
       number([](double x) { return x >= 0 && x < 1; }, "in [0, 1)", "must be in [0, 1)")},
      {"--shadow-res", "PIXELS", "Instant radiosity: each VPL's hemispherical shadow map, pixels a side",
       CLI::Range(8, 2048)},
      {"--shading", "PATH", "Instant radiosity: forward (a scene pass per VPL batch) or deferred (G-buffer)",
       names({"forward", "deferred"})},
      {"--interleave", "N",
       "Instant radiosity: interleaved sampling, each pixel of an N x N tile shades with 1/N^2 of the VPLs, then a "
       "filter over the tile's pixels of the same polygon (1: every VPL at every pixel, exact)",
       CLI::Range(1, 16)},
      {"--sync-timings", "",
       "Exact per-pass times: wait for the GPU at every stage (slower on a GPU; what llvmpipe always does)", none},
  };
}

std::vector<Flag> deviceAndOutputFlags() {
  const auto any = number([](double) { return true; }, "", "must be a number");
  const CLI::Validator none = kNone;
  return {
      // The GL backend.
      {"--backend", "NAME", "GL backend: osmesa, egl or auto",
       enumeration<gl::BackendKind>(
           {{"osmesa", gl::BackendKind::OSMesa}, {"egl", gl::BackendKind::Egl}, {"auto", gl::BackendKind::Auto}}),
       "osmesa"},
      {"--gpu", "INDEX", "EGL device index", CLI::Range(0, 1023), "the first hardware device"},
      {"--gl-debug", "", "Report GL errors through KHR_debug", none},
      // Cameras and images.
      {"--camera", "CAMERA", "eye=x,y,z,target=x,y,z,up=x,y,z,fov=degrees", none,
       "SCENE.camera, else the framed bounds"},
      {"--width", "PIXELS", "Image (or window) width", kPixels},
      {"--height", "PIXELS", "Image (or window) height", kPixels},
      {"--supersample", "N|auto",
       fmt::format("Samples per pixel side, a regular N x N grid box-filtered (anti-aliasing toward the pixel's "
                   "integral, as `reference` estimates it); above 8 the framebuffer stays 8 x (or N's largest divisor "
                   "up to 8) and is drawn again shifted, (N / that)^2 times (--method instant: at most 8); auto: {} "
                   "for an exact camera image (--image-plan), else {}",
                   kExactImagesSupersample, kDefaultSupersample),
       autoOr(kAutoSupersample, 1, 64)},
      {"--image-plan", "PLAN",
       fmt::format("Camera images (--out, --image): quick (the elements' light looked up, {0} x {0} samples a pixel), "
                   "exact (issue 31's refinements: contact cuts, per-pixel direct light, the near final gather, {1} x "
                   "{1} samples; 10-100x the time on llvmpipe) or auto: exact where one solve stops at --converge "
                   "{2:g} or more on a GPU, else quick; --discontinuities, --direct, --final-gather and "
                   "--supersample given override their part (docs/solve.md#exact-images)",
                   kDefaultSupersample, kExactImagesSupersample, kExactImagesFrom),
       enumeration<ImagePlan>({{"auto", ImagePlan::Auto}, {"quick", ImagePlan::Quick}, {"exact", ImagePlan::Exact}}),
       "auto"},
      {"--msaa", "N",
       "Coverage samples in each supersample cell of --out and --image (MSAA at the GPU's fixed positions): edges are "
       "found at N x the --supersample grid's samples while each cell's surface is shaded once, at its centroid "
       "(llvmpipe offers 4; walkthrough and animation frames, the viewer and validate's figures take 1; not with "
       "--method instant; "
       "docs/adaptive.md#msaa)",
       CLI::Validator(CLI::IsMember(std::vector<int>{1, 2, 4, 8, 16, 32})).description("1|2|4|8|16|32")},
      {"--exposure", "STOPS", "Exposure in stops over the automatic one", any},
      {"--ambient", "on|off",
       "Seed 004's ambient term R x (area-averaged unshot radiosity; weighted by received importance in importance- "
       "and perspective-driven solves) x rho on camera images: a preview's estimate of the light not yet shot, so on "
       "in view, walkthrough and experiment frames and off for a solve's images; never in B, the report, the atlas "
       "or the PLY, nor with --method stochastic (nothing is unshot)",
       oneOf(std::map<std::string, bool>{{"on", true}, {"off", false}}, "on|off"), "on"},
      // Outputs.
      {"--out", "FILE", "Camera render: linear (.exr), or tone-mapped like --image (.png)", none},
      {"--out-dir", "DIR",
       "Folder for the CSVs, summary and plots (default: a new ./hemirad-COMMAND, never an earlier run's)", none},
      {"--image", "FILE", "Tone-mapped camera render (.png)", none},
      {"--atlas", "FILE", "Radiosity atlas, one texel per element (.exr)", none},
      {"--ply", "FILE", "Mesh with per-vertex radiosity (.ply)", none},
      {"--gltf", "FILE",
       "Scene with its lightmap (TEXCOORD_1) as glTF 2.0 (X.glb, the lightmap PNG tone mapped as --image inside it), "
       "with X.lightmap.exr (linear B) beside it (not beside a stream)",
       none},
      {"--report", "FILE", "Report (.json; - writes it to stdout)", none},
      {"--json", "FILE", "Results as JSON", none},
      {"--markdown", "FILE", "The printed tables as markdown (e.g. into docs/bench)", none},
      {"--quiet", "", "No progress bar", none},
      // Checkpoints.
      {"--checkpoint", "FILE",
       "Write the solve's state here (X.ckpt, atomically) at the end, on SIGINT/SIGTERM and every --checkpoint-every "
       "shots",
       none},
      {"--checkpoint-every", "N", "Also checkpoint every N shots", kCount},
      {"--resume", "FILE", "Continue from a checkpoint of the same scene and parameters", CLI::ExistingFile},
  };
}

std::vector<Flag> frameAndCommandFlags() {
  const CLI::Validator none = kNone;
  return {
      // Walkthroughs, experiments and the viewer: frames along a camera path or in a window.
      {"--camera-path", "FILE",
       "Walkthrough: keyframes 'TIME eye=.. target=.. fov=..' per line (docs/walkthroughs.md); writes a frame per "
       "1/--fps s and frames.csv into --frames",
       CLI::ExistingFile},
      {"--frames", "DIR", "Folder for the frames and frames.csv (a walkthrough's, animate's)", none},
      {"--light-path", "FILE",
       "Animate: keyframes 'TIME DX DY DZ' per line, the emitters' offset (docs/solve.md, Moving lights); a frame "
       "per 1/--fps s",
       none},
      {"--window", "N", "Animate: the running mean weighs iterations over an exponential window of about N",
       CLI::Range(1u, 1u << 20)},
      {"--keep-frames", "", "Also keep every frame as OUT-DIR/SCENE_ALGORITHM/frame_NNNN.png", none},
      {"--fps", "FPS", "Frames per second of path time (a walkthrough's camera path, animate's light path)",
       CLI::Range(0.01, 1000.0)},
      {"--frame-ms", "MS", "Solver milliseconds per frame", CLI::Range(1.0, 1e7)},
      {"--frame-shots", "N",
       "Instead of --frame-ms: shots per frame (reproducible; rounded up to whole passes of --shooters-per-pass)",
       CLI::Range(1u, 1u << 20), "none: --frame-ms"},
      {"--frame-count", "N", "Quit after N frames (with --frame-shots the solve also stops at N x --frame-shots shots)",
       kCount, "when the window closes"},
      {"--reference-convergence", "C", "Convergence of the reference the frames are compared with",
       CLI::Range(0.5, 0.99999)},
      {"--screenshot", "FILE", "On quit, write the window's last frame here (.png)", none},
      // Sweeps (hemirad experiment SPEC).
      {"--slurm", "DIR", "Write the sweep's Slurm job array into DIR (sweep.sbatch, one task per configuration)", none},
      {"--jobs", "N", "Run the sweep here into --out-dir, N configurations at a time", CLI::Range(1, 1024)},
      // validate.
      {"--levels", "L", "Item-mesh subdivision levels to compare", kLevel},
      {"--shooters", "N|all", "Shooter elements: a count spread over the scene, or all",
       CLI::Validator(
           [](std::string& s) {
             return s == "all" || (!s.empty() && s.size() < 10 &&
                                   s.find_first_not_of("0123456789") == std::string::npos && std::stoul(s) > 0)
                        ? std::string()
                        : "must be a count or 'all'";
           },
           "")},
      {"--figures", "DIR", "Write plots, CSV, heat maps and index.html into this folder", none},
      {"--figure-size", "SIZE",
       "Figures for papers: column (3.5 x 2.6 in), page (7 x 4.2 in) or W,H in inches; fonts embedded, titles in "
       "the metadata, not drawn",
       none, "6.4,4.2 (maps 6.4,5.4)"},
      {"--solution", "", "Also compare a converged GPU solution with the dense exact one (up to 5,000 elements)", none},
      // bench.
      {"--split-shots", "N", "Shots timed pass by pass for the split", CLI::Range(1u, 1u << 20)},
      {"--atlas-sides", "N", "Stochastic iteration: a row per atlas side, the texel size chosen to fill it",
       CLI::Range(16, 16384)},
      {"--compare", "FILE", "Another bench JSON: print per-object differences to its matching rows", none},
      // reference and compare (issue 31, docs/reference.md).
      {"--spp", "N",
       "Reference: paths per pixel over all batches, a multiple of --batches; the standard error falls as "
       "1/sqrt(N) (the Cornell box at 128^2 on 2 llvmpipe cores: 6 s at 16, 23 s at 64 with 7 % noise a pixel, "
       "docs/reference.md#speed)",
       CLI::Range(1u, 1u << 24)},
      {"--batches", "K", "Reference: independent batches, whose spread gives each pixel's standard error",
       CLI::Range(2u, 1024u)},
      {"--bounces", "N",
       "Reference: reflections a path may take before the camera: 1 is the direct light on what the camera sees "
       "(what solve --direct per-pixel computes), 0 the emitters alone; Russian roulette ends paths unbiased below "
       "the cap (docs/reference.md#bounces)",
       CLI::Range(0u, kReferenceBounceCap), fmt::format("{} (unlimited)", kReferenceBounceCap)},
      {"--stderr", "FILE",
       "The reference's per-pixel standard error of B (.exr): reference writes it, compare reads image B's (a noise "
       "column)",
       none},
      {"--scene", "SCENE", "The scene both images show: its edges and creases, traced from --camera, give the regions",
       kScene},
      {"--error-map", "FILE", "The signed relative error per pixel (.png): red where A is brighter, blue darker", none},
      {"--error-range", "F", "The error map's full colour: a relative error of F",
       number([](double x) { return x > 0; }, "> 0", "must be above 0")},
      {"--ceiling", "",
       "Also measure the device's ceilings (load-store invocations/s, item-buffer triangles/s) and print each "
       "throughput as a fraction of them",
       none},
  };
}

std::vector<Flag> makeTable() {
  std::vector<Flag> flags = sceneAndSolverFlags();
  for (auto part : {deviceAndOutputFlags(), frameAndCommandFlags()})
    flags.insert(flags.end(), part.begin(), part.end());
  return flags;
}

}  // namespace

const std::vector<Flag>& table() {
  static const std::vector<Flag> flags = makeTable();
  return flags;
}

const Flag& flag(const std::string& name) {
  for (const Flag& f : table())
    if (f.name == name) return f;
  throw std::logic_error("no flag " + name + " in the option table (src/options/Options.cpp)");
}

CLI::Option* detail::finish(CLI::Option* option, const Flag& f, bool list, const std::string& defaultText) {
  option->type_name(f.value);
  if (list) option->delimiter(',');
  option->transform(f.check);  // a transform both checks and (for names) converts
  if (!defaultText.empty())
    option->default_str(defaultText);
  else if (!f.defaultText.empty())
    option->default_str(f.defaultText);
  else
    option->capture_default_str();
  return option;
}

CLI::Option* addSwitch(CLI::App* cmd, const std::string& name, bool& target) {
  const Flag& f = flag(name);
  return cmd->add_flag(f.name, target, f.help);
}

CLI::Option* declare(CLI::App* cmd, const std::string& name, const std::string& defaultText, const std::string& value) {
  const Flag& f = flag(name);
  if (f.value.empty()) return cmd->add_flag(f.name, f.help);  // a switch
  CLI::Option* option = detail::finish(cmd->add_option(f.name, f.help), f, false, defaultText);
  if (option->get_default_str().empty()) option->default_str(value);
  return option;
}

namespace {

std::string autoText(int value, int autoValue) {
  return fmt::format("{} (preset {})", settingText(value, autoValue), kDefaultPreset);
}

}  // namespace

std::string defaultText(const std::string& flag) {
  if (flag == "--hemisphere")
    return fmt::format("{} (preset {})", projectionName(kFastPlan.projection), kDefaultPreset);
  if (flag == "--item-subdiv") return fmt::format("{} (preset {})", kFastPlan.itemSubdivision, kDefaultPreset);
  if (flag == "--item-res") return autoText(kFastPlan.itemResolution, kAutoItemResolution);
  if (flag == "--shoot-level") return autoText(kFastPlan.shootLevel, kAutoShootLevel);
  if (flag == "--refine-near")
    return fmt::format("{} (preset {})", refineNearText(kFastPlan.refineNear), kDefaultPreset);
  throw std::logic_error(flag + " is not set by a preset");
}

void applyPreset(ProgressiveSettings& p, const std::string& name,
                 const std::function<bool(const std::string&)>& given) {
  const ItemPlan before = p.plan();  // a flag given beside the preset may already be stored
  p.usePreset(name);
  if (given("--hemisphere")) p.projection = before.projection;
  if (given("--item-subdiv")) p.itemSubdivision = before.itemSubdivision;
  if (given("--item-res")) p.itemResolution = before.itemResolution;
  if (given("--shoot-level")) p.shootLevel = before.shootLevel;
  if (given("--refine-near")) p.refineNear = before.refineNear;
}

void addItemPlan(CLI::App* cmd, ProgressiveSettings& p, bool shootLevel) {
  add(cmd, "--preset", p.preset)->each([cmd, &p](const std::string& name) {
    applyPreset(p, name, [cmd](const std::string& flag) {
      const CLI::Option* o = cmd->get_option_no_throw(flag);
      return o && o->count() > 0;
    });
  });
  add(cmd, "--hemisphere", p.projection, defaultText("--hemisphere"));
  add(cmd, "--item-subdiv", p.itemSubdivision, defaultText("--item-subdiv"));
  add(cmd, "--item-res", p.itemResolution, defaultText("--item-res"));
  if (shootLevel) add(cmd, "--shoot-level", p.shootLevel, defaultText("--shoot-level"));
  if (shootLevel) add(cmd, "--refine-near", p.refineNear, defaultText("--refine-near"));
  if (shootLevel) add(cmd, "--visibility", p.visibility);
}

Projection oneProjection(int stored) {
  if (stored == kAllProjections)
    throw InputError("--hemisphere must be orthographic, hemicube, conformal or equal-area, not 'all' (validate's)");
  return Projection(stored);
}

CLI::Validator oneOfNames(const std::vector<std::string>& names) {
  return CLI::Validator(CLI::IsMember(names, CLI::ignore_case)).description(fmt::format("{}", fmt::join(names, "|")));
}

}  // namespace hemirad::options
