// Camera render of a solution: the scene's polygons rasterised with a perspective camera,
// each fragment looking B up in the atlas (bilinear, masked to its own polygon).
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "gl/Objects.h"
#include "src/output/DirectLight.h"
#include "src/output/DirectShares.h"
#include "src/output/DrawBands.h"
#include "src/output/Image.h"
#include "src/output/NearGather.h"
#include "src/output/ShownRadiosity.h"
#include "src/scene/Camera.h"
#include "src/solver/CameraMesh.h"
#include "src/solver/SolverState.h"

namespace hemirad {

class Renderer {
 public:
  explicit Renderer(const SolverState& state);
  // Seed 004's ambient term (shaders/ambient.comp) on what is shown: for previews. Off (the
  // default) shows B exactly, as reports and validation need.
  void setAmbient(bool on) { ambient_ = on; }
  // The term rho_j A adds to element j: A = R S per channel (RGB), from the current dB.
  glm::vec3 ambientTerm();
  // Samples each pixel on a regular supersample x supersample grid and box-filters down
  // (deterministic anti-aliasing; src/output/Supersample.h).
  Image render(const Camera& camera, int width, int height, int supersample = 2);
  // The same view of any per-element RGBA32F atlas (e.g. an error map) instead of B.
  Image render(const Camera& camera, int width, int height, int supersample, const gl::Texture& atlasValues);
  // From now on render() shows these values (atlas order) instead of B: what is shown of B
  // (src/output/ShownRadiosity.h); the ambient term still applies.
  void show(const std::vector<glm::vec4>& values);
  // Live views (the viewer, walkthroughs, animations): from now on each render() shows what is
  // shown of the current B (src/output/ShownRadiosity.h: buried texels filled, seams stitched),
  // read back per call. Off, render() shows B (or what show() gave) exactly.
  void stitchLive();
  // `--direct per-pixel`: from now on render() shows E + each pixel's direct light, computed
  // exactly (shaders/direct.glsl), + the shown values, which must then be the indirect part
  // (src/solver/DirectSplit.h); with `gather` (`--final-gather near`) each pixel also regathers
  // the light of the elements near it (shaders/near_gather.glsl). The renderer keeps both.
  void usePerPixelDirect(const DirectLight& direct, const NearGather* gather = nullptr);
  // How the per-pixel pass is split into bands (tests split it finely).
  void setBandPlan(const BandPlan& plan) { bands_ = plan; }
  // `--msaa`: coverage samples a framebuffer pixel (src/output/CameraTarget.h); 1 by default.
  void setMultisample(int samples) { samples_ = samples; }
  // The samples a cell the last render drew: setMultisample's, or 1 where cameraPlan fell back.
  int lastSamples() const { return lastSamples_; }
  // The shares the last render's per-pixel pass was drawn in: {1, 1}, or more where llvmpipe's
  // loop limit cut a walk (render(), src/output/DirectShares.h).
  SharePlan lastShares() const { return shares_.value_or(SharePlan{}); }

 private:
  const gl::Texture& shown() const { return shown_ ? *shown_ : state_.radiosity; }

  const SolverState& state_;
  void updateAmbient();

  enum class Cut { None, Direct, Gather, Both };  // the part of the per-pixel pass whose walks were cut
  Image draw(const Camera& camera, int width, int height, int supersample, const gl::Texture& atlasValues,
             bool perPixel, Cut& cut);
  Cut drawDirect(const glm::mat4& vp, int width, int height);

  gl::Program program_, ambientProgram_, directProgram_;
  const DirectLight* direct_ = nullptr;
  const NearGather* gather_ = nullptr;
  BandPlan bands_;
  gl::Buffer ambientTerm_;
  CameraMesh mesh_;
  bool ambient_ = false;
  int samples_ = 1, lastSamples_ = 1;
  std::optional<SharePlan> shares_;  // the last view's; none yet
  std::unique_ptr<gl::Texture> shown_;
  std::unique_ptr<ShownRadiosity> stitcher_;  // stitchLive(), where what is shown differs from B
};

// A camera render's read-back RGBA: every pixel's alpha is 1, the clear's, kept by the first
// pass (alpha 1) and the direct pass (adding alpha 0). One that is not came from a GPU that
// dropped the draws (an H100 read back zeros, alpha too, with no GL error, after an 11 s draw,
// which src/output/DrawBands.h now prevents): throws, so a run fails with one error line
// instead of writing a black image and exiting 0.
void requireDrawn(const std::vector<float>& rgba);

}  // namespace hemirad
