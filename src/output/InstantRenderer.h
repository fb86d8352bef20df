// Instant radiosity's camera images (seed 002): every VPL's hemispherical shadow map
// (VplShadowMaps, rendered again only when the VPLs change), then forward or deferred shading
// summing the VPL batches, optionally interleaved (n x n VPL subsets, then a geometry-aware
// filter). Like Renderer it shades camera pixels; unlike it there is no atlas: B is per pixel.
#pragma once
#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "src/output/Image.h"
#include "src/output/VplShadowMaps.h"
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
  static constexpr int kBatch = VplShadowMaps::kBatch;  // VPLs per shadow-map draw and shading pass

  InstantRenderer(const Scene& scene, const VplTracer& tracer, const InstantSettings& settings);
  // Renders at supersample x the size and box-filters down, as Renderer does.
  InstantImage render(const Camera& camera, int width, int height, int supersample, Shading shading);
  // One frame into the internal target: the shadow maps if the VPLs changed, then the shading
  // (G-buffer, the VPL batches, the interleaving filter). A camera move costs the shading only.
  void draw(const Camera& camera, int width, int height, Shading shading);
  // The tracer traced again (new VPLs): the next draw renders every shadow map first.
  void vplsChanged() { shadowsStale_ = true; }
  // After a draw: each pixel's polygon (kNoPolygon: background), rows top-down.
  std::vector<std::uint32_t> visiblePolygons() const;

 private:
  void resize(int width, int height);
  void gBuffer(const Camera& camera, const glm::mat4& vp);
  void shadeForward(const glm::mat4& vp, unsigned batch);
  void shadeDeferred(unsigned batch);
  void filter(Shading shading);
  void setBatch(const gl::Program& program, unsigned batch) const;
  const gl::Texture& result(Shading shading) const;

  const VplTracer& tracer_;
  VplShadowMaps shadows_;
  bool shadowsStale_ = true;
  unsigned vpls_;
  int interleave_;
  glm::dvec3 boundsMin_, boundsMax_;
  gl::Program forward_, gbuffer_, deferred_, filter_;
  gl::Buffer sceneVertices_;
  gl::VertexArray sceneVao_;
  std::size_t sceneVertexCount_ = 0;
  int width_ = 0, height_ = 0;
  glm::ivec2 sub_{0};                                        // a de-interleaved block: ceil(size / n)
  gl::Texture color_, shaded_, filtered_, polygon_, depth_;  // polygon_: the G-buffer (id + 1)
  gl::Framebuffer colorTarget_, gTarget_;
};

}  // namespace hemirad
