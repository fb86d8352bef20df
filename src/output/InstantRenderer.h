// Instant radiosity's camera images (seed 002): hemispherical shadow maps for every VPL (one
// layered draw per batch of VPLs), then forward or deferred shading summing the batches. Like
// Renderer it shades camera pixels; unlike it there is no atlas: B is computed per pixel.
#pragma once
#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "src/output/Image.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"
#include "src/solver/VplTracer.h"

namespace hemirad {

enum class Shading { Forward, Deferred };
const char* shadingName(Shading s);

// A render and what the clamp of the geometry term took out of it (luminance summed over the
// image's pixels, against the clamped image's own sum): the clamp's bias, measured in the shader.
struct InstantImage {
  Image image;
  double clampRemoved = 0, luminanceSum = 0;
  double clampBias() const { return clampRemoved / (luminanceSum + clampRemoved); }  // fraction of the light
};

class InstantRenderer {
 public:
  static constexpr int kBatch = 256;  // VPLs per shadow-map draw (layers) and shading pass

  InstantRenderer(const Scene& scene, const VplTracer& tracer, const InstantSettings& settings);
  // Renders at supersample x the size and box-filters down, as Renderer does.
  InstantImage render(const Camera& camera, int width, int height, int supersample, Shading shading);
  // One frame into the internal target (the bench's unit of work): shadow maps, then shading.
  void draw(const Camera& camera, int width, int height, Shading shading);
  // After a deferred draw: each pixel's polygon (kNoPolygon: background), rows top-down.
  std::vector<std::uint32_t> visiblePolygons() const;

 private:
  void resize(int width, int height);
  void shadowBatch(unsigned first, unsigned count);
  void shadeForward(const glm::mat4& vp, unsigned first, unsigned count);
  void shadeDeferred(unsigned first, unsigned count);
  void setBatch(const gl::Program& program, unsigned first, unsigned count) const;

  const VplTracer& tracer_;
  unsigned vpls_;
  int shadowSize_;
  float far_, maxGeometry_;
  glm::dvec3 boundsMin_, boundsMax_;
  gl::Program shadow_, forward_, gbuffer_, deferred_;
  gl::Buffer itemVertices_, itemIndices_, sceneVertices_;
  gl::VertexArray itemVao_, sceneVao_, emptyVao_;
  std::size_t itemIndexCount_ = 0, sceneVertexCount_ = 0;
  gl::Texture shadowId_, shadowDepth_;
  gl::Framebuffer shadowTarget_;
  int width_ = 0, height_ = 0;
  gl::Texture color_, position_, depth_;
  gl::Framebuffer colorTarget_, gTarget_;
};

}  // namespace hemirad
