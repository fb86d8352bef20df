// `hemirad solve` and `hemirad info`: the commands, apart from flag parsing (src/cli/main.cpp).
#pragma once
#include <optional>
#include <string>

#include "gl/Backend.h"
#include "src/base/OutputPaths.h"
#include "src/method/MethodUnit.h"
#include "src/output/Image.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Presets.h"
#include "src/solver/Subdivide.h"
#include "src/walk/Walkthrough.h"

namespace hemirad {

struct SolveOptions {
  std::string scene;
  LoadOptions load;
  Discretisation discretisation;
  SubdivideOptions subdivide;    // --subdivide, --leaf-depth, --split-gradient
  bool discontinuities = false;  // --discontinuities contact (auto: MethodUnit::exactImages)
  // --image-plan, and whether the backend will be a GPU (gl::rendersOnCpu): what the method's
  // exactImages() follows (docs/solve.md#exact-images).
  ImagePlan imagePlan = ImagePlan::Auto;
  bool gpu = false;
  std::string methodName = "progressive";  // --method
  const MethodUnit* method = nullptr;      // that method, its own flags bound (Commands::settle)
  gl::BackendOptions backend;
  std::optional<std::string> camera;
  int width = 512, height = 512, supersample = 2;
  // Coverage samples a supersample cell (src/output/CameraTarget.h); unset: kDefaultMsaa or the
  // backend's most if fewer (llvmpipe: 4), or 1 where a method draws its own images (instant).
  std::optional<int> msaa;
  static constexpr int kDefaultMsaa = 8;  // the H100's best edges: 16 and 32 find them worse
  double exposure = 0;                    // stops over the automatic exposure
  // Seed 004's ambient term on the camera images (never on B, report, atlas, PLY): a preview's device,
  // so on for --camera-path frames and off for a solve's own images unless given (issue 31).
  std::optional<bool> ambient;
  std::string out, image, atlas, ply, report;
  std::string gltf;              // OUT.glb, with OUT.lightmap.exr and OUT.lightmap.png beside it
  std::string checkpoint;        // written every checkpointEvery shots, at the end and on SIGINT/SIGTERM
  unsigned checkpointEvery = 0;  // 0: only at the end and on a signal
  std::string resume;            // a checkpoint to continue from
  // A walkthrough instead of one image: frames along the path into walkthrough.framesDir, with
  // frames.csv beside them; the reference is progressive refinement to referenceConvergence.
  std::string cameraPath;
  WalkthroughOptions walkthrough;
  double referenceConvergence = 0.99;
  bool progress = true;

  // One solve's camera image: --out or --image, not a walkthrough's frames.
  bool cameraImage() const { return cameraPath.empty() && (!out.empty() || !image.empty()); }
};

// Runs options.method; the methods with a Solver through AtlasMethod::solve (Solve.cpp).
int runSolve(const SolveOptions& options);
// Before any work: every output's name and folder, no two outputs on one file or stream, and none
// on `inputs` (the scene and what it names; --resume's checkpoint unless --checkpoint is it).
void checkSolveOutputs(const SolveOptions& options, std::vector<InputPath> inputs);
// FNV-1a 64 of an image's float bit patterns (determinism checks).
std::uint64_t imageHash(const Image& image);

struct InfoOptions {
  std::string scene;
  LoadOptions load;
  Discretisation discretisation;
  int itemSubdivision = kFastPlan.itemSubdivision;  // the item mesh a solve's default preset draws
};

int runInfo(const InfoOptions& options);

}  // namespace hemirad
