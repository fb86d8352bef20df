#include "src/output/InstantRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gl/Debug.h"
#include "gl/State.h"
#include "src/scene/Atlas.h"
#include "src/scene/ItemMesh.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

const char* shadingName(Shading s) { return s == Shading::Forward ? "forward" : "deferred"; }

InstantRenderer::InstantRenderer(const Scene& scene, const VplTracer& tracer, const InstantSettings& settings)
    : tracer_(tracer),
      shadows_(scene, tracer, settings),
      vpls_(settings.vpls),
      interleave_(std::max(1, settings.interleave)),
      boundsMin_(scene.boundsMin()),
      boundsMax_(scene.boundsMax()),
      forward_(renderProgram("instant.vert", "instant_forward.frag")),
      gbuffer_(renderProgram("instant.vert", "instant_gbuffer.frag")),
      deferred_(computeProgram("instant_deferred.comp")),
      filter_(computeProgram("instant_filter.comp")) {
  const float far = float(2.0 * tracer.sceneDiagonal() + 1e-6);
  float maxGeometry = float(1.0 / std::pow(settings.clamp * tracer.sceneDiagonal(), 2.0));
  if (settings.clamp <= 0) maxGeometry = 3.4e38f;                     // no clamp
  const std::vector<ItemVertex> triangles = buildItemMesh(scene, 0);  // the polygons, fanned
  sceneVertexCount_ = triangles.size();
  sceneVertices_ = gl::Buffer(std::span<const ItemVertex>(triangles));
  sceneVao_.vertexBuffer(sceneVertices_, sizeof(ItemVertex));
  sceneVao_.floatAttribute(0, 3, offsetof(ItemVertex, x));
  sceneVao_.uintAttribute(1, offsetof(ItemVertex, polygon));
  const unsigned n = unsigned(interleave_);
  for (const gl::Program* p : {&forward_, &deferred_}) {
    p->set("maxGeometry", maxGeometry);
    p->set("farDistance", far);
    p->set("interleaveM", n * n);
  }
  for (const gl::Program* p : {&forward_, &deferred_, &filter_}) p->set("interleave", n);
}

void InstantRenderer::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width, height_ = height;
  sub_ = (glm::ivec2(width, height) + interleave_ - 1) / interleave_;
  color_ = gl::Texture(GL_RGBA32F, width, height);
  shaded_ = gl::Texture(GL_RGBA32F, sub_.x * interleave_, sub_.y * interleave_);
  if (interleave_ > 1) filtered_ = gl::Texture(GL_RGBA32F, width, height);
  polygon_ = gl::Texture(GL_R32UI, width, height);
  depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
  colorTarget_ = gl::Framebuffer();
  colorTarget_.attach(GL_COLOR_ATTACHMENT0, color_);
  colorTarget_.attach(GL_DEPTH_ATTACHMENT, depth_);
  colorTarget_.checkComplete("instant radiosity image");
  gTarget_ = gl::Framebuffer();
  gTarget_.attach(GL_COLOR_ATTACHMENT0, polygon_);
  gTarget_.attach(GL_DEPTH_ATTACHMENT, depth_);
  gTarget_.checkComplete("G-buffer");
  for (const gl::Program* p : {&deferred_, &filter_}) p->set("sub", sub_.x, sub_.y);
}

// The visible polygon per pixel, and the camera's pixel rays the shading passes meet its plane
// with; forward shading's depth pre-pass too (the same vertex shader, invariant: its later passes
// meet these depths exactly).
void InstantRenderer::gBuffer(const Camera& camera, const glm::mat4& vp) {
  const Camera::PixelRays rays = camera.pixelRays(width_, height_);
  for (const gl::Program* p : {&forward_, &deferred_}) {
    for (auto [name, v] :
         {std::pair{"eye", camera.eye}, {"rayCorner", rays.corner}, {"rayDx", rays.dx}, {"rayDy", rays.dy}})
      p->set(name, float(v.x), float(v.y), float(v.z));
  }
  gTarget_.clearColor(std::uint32_t(0));
  gTarget_.clearDepth(0.0f);
  gTarget_.bind();
  gl::cameraView(width_, height_).apply();
  gbuffer_.set("viewProjection", &vp[0][0]);
  gbuffer_.use();
  sceneVao_.bind();
  gl::drawTriangles(sceneVertexCount_);
  gl::barrier(gl::Barrier::TextureFetch);
}

void InstantRenderer::setBatch(const gl::Program& program, unsigned batch) const {
  const unsigned first = batch * kBatch;
  program.set("vplFirst", first);
  program.set("vplCount", std::min<unsigned>(kBatch, vpls_ - first));
  program.set("addEmission", int(batch == 0));
  tracer_.bind();
  shadows_.bind(batch, slot::SAMPLER_SHADOW_ID);
}

void InstantRenderer::shadeForward(const glm::mat4& vp, unsigned batch) {
  colorTarget_.bind();
  auto state = gl::cameraView(width_, height_);
  state.depthFunc = gl::DepthFunc::Equal, state.depthWrite = false, state.additiveBlend = true;
  state.apply();
  setBatch(forward_, batch);
  forward_.set("viewProjection", &vp[0][0]);
  forward_.use();
  sceneVao_.bind();
  gl::drawTriangles(sceneVertexCount_);
}

void InstantRenderer::shadeDeferred(unsigned batch) {
  setBatch(deferred_, batch);
  polygon_.bindUnit(slot::SAMPLER_G_POLYGON);
  shaded_.bindImage(slot::IMAGE_SHADED, GL_READ_WRITE);
  deferred_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(shaded_.width()), 8), gl::groupsFor(unsigned(shaded_.height()), 8));
  gl::barrier(gl::Barrier::Image | gl::Barrier::TextureFetch | gl::Barrier::TextureUpdate);
}

void InstantRenderer::filter(Shading shading) {
  if (shading == Shading::Forward) gl::barrier(gl::Barrier::Image | gl::Barrier::Framebuffer);
  polygon_.bindUnit(slot::SAMPLER_G_POLYGON);
  (shading == Shading::Forward ? color_ : shaded_).bindImage(slot::IMAGE_SHADED, GL_READ_ONLY);
  filtered_.bindImage(slot::IMAGE_FILTERED, GL_WRITE_ONLY);
  filter_.set("deinterleaved", int(shading == Shading::Deferred));
  filter_.use();
  gl::Program::dispatch(gl::groupsFor(unsigned(width_), 8), gl::groupsFor(unsigned(height_), 8));
  gl::barrier(gl::Barrier::Image | gl::Barrier::TextureUpdate);
}

const gl::Texture& InstantRenderer::result(Shading shading) const {
  if (interleave_ > 1) return filtered_;
  return shading == Shading::Forward ? color_ : shaded_;
}

void InstantRenderer::draw(const Camera& camera, int width, int height, Shading shading) {
  if (shadowsStale_ || !shadows_.rendered()) shadows_.render(), shadowsStale_ = false;
  resize(width, height);
  // The camera's reversed-Z projection, its near plane in front of the whole scene.
  const glm::mat4 vp = camera.viewProjection(double(width) / height, nearPlane(camera, boundsMin_, boundsMax_));
  gBuffer(camera, vp);
  if (shading == Shading::Forward) colorTarget_.clearColor(0, 0, 0, 0);
  for (unsigned b = 0; b < shadows_.batches(); ++b) {
    if (shading == Shading::Forward)
      shadeForward(vp, b);
    else
      shadeDeferred(b);
  }
  if (interleave_ > 1) filter(shading);
  gl::checkErrors("instant radiosity render");
}

std::vector<std::uint32_t> InstantRenderer::visiblePolygons() const {
  std::vector<std::uint32_t> g(std::size_t(width_) * height_);
  polygon_.read(GL_RED_INTEGER, GL_UNSIGNED_INT, g.size() * sizeof(std::uint32_t), g.data());
  std::vector<std::uint32_t> ids(g.size());
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const std::uint32_t id = g[std::size_t(y) * width_ + x];
      ids[std::size_t(height_ - 1 - y) * width_ + x] = id ? id - 1 : kNoPolygon;
    }
  return ids;
}

InstantImage InstantRenderer::render(const Camera& camera, int width, int height, int supersample, Shading shading) {
  const int s = std::max(1, supersample), w = width * s, h = height * s;
  draw(camera, w, h, shading);
  // The deferred image without interleaving is stored in blocks of one: image order, padded to w x h.
  const gl::Texture& shaded = result(shading);
  std::vector<float> rgba(std::size_t(shaded.width()) * shaded.height() * 4);
  shaded.read(GL_RGBA, GL_FLOAT, rgba.size() * sizeof(float), rgba.data());
  const int stride = shaded.width();
  InstantImage out{{width, height, std::vector<float>(std::size_t(width) * height * 3, 0.0f)}};
  const float norm = 1.0f / float(s * s);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0;
        for (int j = 0; j < s; ++j)
          for (int i = 0; i < s; ++i) sum += rgba[(std::size_t(y * s + j) * stride + (x * s + i)) * 4 + c];
        if (c == 3) {
          out.clampRemoved += sum * norm;
          continue;
        }
        // GL rows go bottom-up; images go top-down.
        out.image.rgb[(std::size_t(height - 1 - y) * width + x) * 3 + c] = float(sum) * norm;
      }
  for (std::size_t p = 0; p < out.image.rgb.size(); p += 3)
    out.luminanceSum += luminance(glm::dvec3(out.image.rgb[p], out.image.rgb[p + 1], out.image.rgb[p + 2]));
  return out;
}

}  // namespace hemirad
