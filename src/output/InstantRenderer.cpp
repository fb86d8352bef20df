#include "src/output/InstantRenderer.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gl/Debug.h"
#include "gl/Shader.h"
#include "gl/State.h"
#include "src/scene/Atlas.h"
#include "src/scene/ItemMesh.h"

namespace hemirad {

const char* shadingName(Shading s) { return s == Shading::Forward ? "forward" : "deferred"; }

InstantRenderer::InstantRenderer(const Scene& scene, const VplTracer& tracer, const InstantSettings& settings)
    : tracer_(tracer),
      vpls_(settings.vpls),
      shadowSize_(settings.shadowResolution),
      far_(float(2.0 * tracer.sceneDiagonal() + 1e-6)),
      maxGeometry_(float(1.0 / std::pow(settings.clamp * tracer.sceneDiagonal(), 2.0))),
      boundsMin_(scene.boundsMin()),
      boundsMax_(scene.boundsMax()),
      shadow_(gl::renderProgram("vpl_shadow.vert", "vpl_shadow.frag")),
      forward_(gl::renderProgram("instant.vert", "instant_forward.frag")),
      gbuffer_(gl::renderProgram("instant.vert", "instant_gbuffer.frag")),
      deferred_(gl::renderProgram("instant_deferred.vert", "instant_deferred.frag")),
      shadowId_(GL_R32UI, shadowSize_, shadowSize_, kBatch),
      shadowDepth_(GL_DEPTH_COMPONENT32F, shadowSize_, shadowSize_, kBatch) {
  if (settings.clamp <= 0) maxGeometry_ = 3.4e38f;  // no clamp
  const IndexedItemMesh item = indexItemMesh(buildItemMesh(scene, settings.itemSubdivision));
  itemIndexCount_ = item.indices.size();
  itemVertices_ = gl::Buffer(std::span<const ItemVertex>(item.vertices));
  itemIndices_ = gl::Buffer(std::span<const std::uint32_t>(item.indices));
  itemVao_.vertexBuffer(itemVertices_, sizeof(ItemVertex));
  itemVao_.floatAttribute(0, 3, offsetof(ItemVertex, x));
  itemVao_.uintAttribute(1, offsetof(ItemVertex, polygon));
  itemVao_.indexBuffer(itemIndices_);
  const std::vector<ItemVertex> triangles = buildItemMesh(scene, 0);  // the polygons, fanned
  sceneVertexCount_ = triangles.size();
  sceneVertices_ = gl::Buffer(std::span<const ItemVertex>(triangles));
  sceneVao_.vertexBuffer(sceneVertices_, sizeof(ItemVertex));
  sceneVao_.floatAttribute(0, 3, offsetof(ItemVertex, x));
  sceneVao_.uintAttribute(1, offsetof(ItemVertex, polygon));
  shadowTarget_.attach(GL_COLOR_ATTACHMENT0, shadowId_);
  shadowTarget_.attach(GL_DEPTH_ATTACHMENT, shadowDepth_);
  shadowTarget_.checkComplete("VPL shadow maps");
  shadow_.set("farDistance", far_);
  shadow_.set("faceSize", float(shadowSize_));
  for (const gl::Program* p : {&forward_, &deferred_}) {
    p->set("maxGeometry", maxGeometry_);
    p->set("farDistance", far_);
  }
}

void InstantRenderer::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width, height_ = height;
  color_ = gl::Texture(GL_RGBA32F, width, height);
  position_ = gl::Texture(GL_RGBA32F, width, height);
  depth_ = gl::Texture(GL_DEPTH_COMPONENT32F, width, height);
  colorTarget_ = gl::Framebuffer();
  colorTarget_.attach(GL_COLOR_ATTACHMENT0, color_);
  colorTarget_.attach(GL_DEPTH_ATTACHMENT, depth_);
  colorTarget_.checkComplete("instant radiosity image");
  gTarget_ = gl::Framebuffer();
  gTarget_.attach(GL_COLOR_ATTACHMENT0, position_);
  gTarget_.attach(GL_DEPTH_ATTACHMENT, depth_);
  gTarget_.checkComplete("G-buffer");
}

// Shadow maps of VPLs [first, first + count) into layers [0, count).
void InstantRenderer::shadowBatch(unsigned first, unsigned count) {
  gl::RasterState{.width = shadowSize_, .height = shadowSize_, .clipDistance0 = true}.apply();
  tracer_.bind();
  shadow_.set("vplFirst", first);
  shadow_.use();
  itemVao_.bind();
  shadowTarget_.clearColor(0xFFFFFFFFu);
  shadowTarget_.clearDepth(1.0f);
  shadowTarget_.bind();
  gl::drawIndexedTriangles(itemIndexCount_, int(count));
}

void InstantRenderer::setBatch(const gl::Program& program, unsigned first, unsigned count) const {
  program.set("vplFirst", first);
  program.set("vplCount", count);
  program.set("addEmission", int(first == 0));
  tracer_.bind();
  shadowId_.bindUnit(4);
}

void InstantRenderer::shadeForward(const glm::mat4& vp, unsigned first, unsigned count) {
  colorTarget_.bind();
  auto state = gl::cameraView(width_, height_);
  if (first == 0) {  // depth pre-pass: the same program adding nothing (no VPLs, no emission)
    state.apply();
    setBatch(forward_, 1, 0);
    forward_.set("viewProjection", &vp[0][0]);
    forward_.use();
    sceneVao_.bind();
    gl::drawTriangles(sceneVertexCount_);
  }
  state.depthFunc = gl::DepthFunc::Equal, state.depthWrite = false, state.additiveBlend = true;
  state.apply();
  setBatch(forward_, first, count);
  forward_.use();
  sceneVao_.bind();
  gl::drawTriangles(sceneVertexCount_);
}

void InstantRenderer::shadeDeferred(unsigned first, unsigned count) {
  colorTarget_.bind();
  gl::RasterState{.width = width_, .height = height_, .depthTest = false, .depthWrite = false, .additiveBlend = true}
      .apply();
  setBatch(deferred_, first, count);
  position_.bindUnit(6);
  deferred_.use();
  emptyVao_.bind();
  gl::drawTriangles(3);
}

void InstantRenderer::draw(const Camera& camera, int width, int height, Shading shading) {
  resize(width, height);
  // The camera's reversed-Z projection, its near plane in front of the whole scene (CameraMesh).
  const glm::dvec3 outside = glm::max(glm::max(boundsMin_ - camera.eye, camera.eye - boundsMax_), glm::dvec3(0.0));
  const double near = std::max(0.5 * glm::length(outside), 1e-6 * glm::length(boundsMax_ - boundsMin_));
  const glm::mat4 vp = camera.viewProjection(double(width) / height, near);
  colorTarget_.clearColor(0, 0, 0, 0);
  colorTarget_.clearDepth(0.0f);
  if (shading == Shading::Deferred) {
    gTarget_.clearColor(0, 0, 0, 0);
    gTarget_.bind();
    gl::cameraView(width, height).apply();
    gbuffer_.set("viewProjection", &vp[0][0]);
    gbuffer_.use();
    sceneVao_.bind();
    gl::drawTriangles(sceneVertexCount_);
    gl::barrier(gl::Barrier::TextureFetch);
  }
  for (unsigned first = 0; first < vpls_; first += kBatch) {
    const unsigned count = std::min<unsigned>(kBatch, vpls_ - first);
    shadowBatch(first, count);
    if (shading == Shading::Forward)
      shadeForward(vp, first, count);
    else
      shadeDeferred(first, count);
  }
  gl::checkErrors("instant radiosity render");
}

std::vector<std::uint32_t> InstantRenderer::visiblePolygons() const {
  std::vector<float> g(std::size_t(width_) * height_ * 4);
  position_.read(GL_RGBA, GL_FLOAT, g.size() * sizeof(float), g.data());
  std::vector<std::uint32_t> ids(std::size_t(width_) * height_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const float w = g[(std::size_t(y) * width_ + x) * 4 + 3];
      ids[std::size_t(height_ - 1 - y) * width_ + x] = w > 0 ? std::uint32_t(w) - 1 : kNoPolygon;
    }
  return ids;
}

InstantImage InstantRenderer::render(const Camera& camera, int width, int height, int supersample, Shading shading) {
  const int s = std::max(1, supersample), w = width * s, h = height * s;
  draw(camera, w, h, shading);
  std::vector<float> rgba(std::size_t(w) * h * 4);
  color_.read(GL_RGBA, GL_FLOAT, rgba.size() * sizeof(float), rgba.data());
  InstantImage out{{width, height, std::vector<float>(std::size_t(width) * height * 3, 0.0f)}};
  const float norm = 1.0f / float(s * s);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0;
        for (int j = 0; j < s; ++j)
          for (int i = 0; i < s; ++i) sum += rgba[(std::size_t(y * s + j) * w + (x * s + i)) * 4 + c];
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
