// The unbiased reference's GPU half (issue 31, docs/reference.md): shaders/reference.comp traces
// Lambertian paths through the BVH instant radiosity uses (src/solver/Bvh.h), with the solver's
// emission semantics (one-sided emitters, pixels in B units), sampling the emitters directly at
// every bounce (src/solver/EmitterTable.h). It returns each batch's per-pixel
// sums; BatchStatistics.h turns them into the mean and its standard error.
#pragma once
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"
#include "src/solver/BvhBuffers.h"

namespace hemirad {

// The most reflections a path takes (shaders/reference.comp's MAX_BOUNCES): roulette ends a path
// before it with probability 1 - 0.99^4096 ~ 1 - 1e-18, so the default is unlimited in effect.
inline constexpr unsigned kReferenceBounceCap = 4096;

struct ReferenceSettings {
  unsigned samples = 64;  // paths per pixel, over all batches (--spp): seconds on llvmpipe at 128^2
  unsigned batches = 16;  // independent batches: the standard error's degrees of freedom + 1
  unsigned seed = 0;
  unsigned bounces = kReferenceBounceCap;  // reflections a path may take (--bounces; 1: direct light only)
  int width = 128, height = 128;
};

// Called after each batch with its per-pixel sums (rows top-down) of samples / batches paths.
using BatchConsumer = std::function<void(const std::vector<glm::vec4>& sums)>;

// Throws InputError for a batch count that does not divide the samples (before any work).
void checkReferenceSettings(const ReferenceSettings& settings);

class PathTracer {
 public:
  explicit PathTracer(const Scene& scene);
  // Hands each batch's sums to `consume` as it finishes (BatchStatistics.h adds them up).
  void render(const Camera& camera, const ReferenceSettings& settings, const BatchConsumer& consume);

 private:
  BvhBuffers bvh_;
  gl::Program program_;
  gl::Buffer polygons_, polygonVertices_, emitters_;
};

}  // namespace hemirad
