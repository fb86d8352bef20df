#include "src/output/LightmapView.h"

#include <cstddef>
#include <span>

#include "gl/Debug.h"
#include "gl/Objects.h"
#include "gl/State.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {

gl::Texture lightmapTexture(const Image& lightmap) {
  std::vector<float> rgba(std::size_t(lightmap.width) * lightmap.height * 4, 1.0f);
  for (std::size_t t = 0; t < rgba.size() / 4; ++t)
    for (int c = 0; c < 3; ++c) rgba[t * 4 + std::size_t(c)] = lightmap.rgb[t * 3 + std::size_t(c)];
  gl::Texture texture(GL_RGBA32F, lightmap.width, lightmap.height);
  texture.upload(GL_RGBA, GL_FLOAT, rgba.data());  // row 0 at t = 0, as glTF's v = 0
  texture.linearFiltering();
  return texture;
}

glm::mat4 viewProjection(const std::vector<LightmapVertex>& triangles, const Camera& camera, double aspect) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const LightmapVertex& v : triangles) {
    const glm::dvec3 p(v.position[0], v.position[1], v.position[2]);
    lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  return camera.viewProjection(aspect, nearPlane(camera, lo, hi));
}

// Boxes s x s samples into a pixel; a pixel's surface is its samples' one if they agree.
LightmapRender downsample(const std::vector<float>& rgba, int width, int height, int s) {
  LightmapRender out{{width, height, std::vector<float>(std::size_t(width) * height * 3, 0.0f)},
                     std::vector<int>(std::size_t(width) * height, -1)};
  const int w = width * s;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = std::size_t(height - 1 - y) * width + x;  // GL rows go bottom-up
      const float first = rgba[(std::size_t(y * s) * w + std::size_t(x * s)) * 4 + 3];
      bool same = true;
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const float* sample = &rgba[(std::size_t(y * s + j) * w + std::size_t(x * s + i)) * 4];
          for (int c = 0; c < 3; ++c) out.image.rgb[pixel * 3 + std::size_t(c)] += sample[c] / float(s * s);
          same = same && sample[3] == first;
        }
      if (same) out.surface[pixel] = first >= 0 ? int(first) : -2;
    }
  return out;
}

}  // namespace

LightmapRender renderLightmapped(const std::vector<LightmapVertex>& triangles, const Image& lightmap,
                                 const Camera& camera, int width, int height, int supersample) {
  const int s = std::max(1, supersample), w = width * s, h = height * s;
  gl::Program program = renderProgram("lightmap.vert", "lightmap.frag");
  gl::Texture texture = lightmapTexture(lightmap);
  gl::Buffer vertices{std::span<const LightmapVertex>(triangles)};
  gl::VertexArray vao;
  vao.vertexBuffer(vertices, sizeof(LightmapVertex));
  vao.floatAttribute(0, 3, offsetof(LightmapVertex, position));
  vao.floatAttribute(1, 2, offsetof(LightmapVertex, uv));
  vao.uintAttribute(2, offsetof(LightmapVertex, surface));

  gl::Texture color(GL_RGBA32F, w, h), depth(GL_DEPTH_COMPONENT32F, w, h);
  gl::Framebuffer fbo;
  fbo.attach(GL_COLOR_ATTACHMENT0, color);
  fbo.attach(GL_DEPTH_ATTACHMENT, depth);
  fbo.checkComplete("lightmap view");
  fbo.clearColor(0, 0, 0, -1);  // alpha -1: no surface
  fbo.clearDepth(0.0f);         // reversed depth, as the camera render
  const glm::mat4 vp = viewProjection(triangles, camera, double(width) / height);
  fbo.bind();
  gl::cameraView(w, h).apply();
  texture.bindUnit(slot::SAMPLER_LIGHTMAP);
  program.set("viewProjection", &vp[0][0]);
  program.use();
  vao.bind();
  gl::drawTriangles(triangles.size());
  gl::checkErrors("lightmap view");

  std::vector<float> rgba(std::size_t(w) * h * 4);
  color.read(GL_RGBA, GL_FLOAT, rgba.size() * sizeof(float), rgba.data());
  return downsample(rgba, width, height, s);
}

}  // namespace hemirad
