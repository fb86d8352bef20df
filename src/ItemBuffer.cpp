#include "src/ItemBuffer.h"

#include "gl/Shader.h"
#include "src/Atlas.h"
#include "src/Control.h"
#include "src/ItemMesh.h"

namespace hemirad {

ItemBuffer::ItemBuffer(const Scene& scene, int subdivision, int resolution, double farDistance)
    : resolution_(resolution),
      program_(gl::renderProgram("itembuffer.vert", "itembuffer.frag")),
      id_(GL_R32UI, resolution, resolution),
      depth_(GL_DEPTH_COMPONENT32F, resolution, resolution) {
  std::vector<ItemVertex> mesh = buildItemMesh(scene, subdivision);
  vertexCount_ = mesh.size();
  vertices_ = gl::Buffer(std::span<const ItemVertex>(mesh));
  vao_.vertexBuffer(vertices_, sizeof(ItemVertex));
  vao_.floatAttribute(0, 3, offsetof(ItemVertex, x));
  vao_.uintAttribute(1, offsetof(ItemVertex, polygon));
  fbo_.attach(GL_COLOR_ATTACHMENT0, id_);
  fbo_.attach(GL_DEPTH_ATTACHMENT, depth_);
  fbo_.checkComplete("item buffer");
  program_.set("farDistance", float(farDistance));
}

void ItemBuffer::render(const gl::Buffer& control) {
  const GLuint clearId[4] = {kNoPolygon, 0, 0, 0};
  const float far = 1.0f;
  glClearNamedFramebufferuiv(fbo_.id(), GL_COLOR, 0, clearId);
  glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
  fbo_.bind();
  glViewport(0, 0, resolution_, resolution_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);  // every face occludes from both sides
  glEnable(GL_CLIP_DISTANCE0);
  control.bindBase(GL_SHADER_STORAGE_BUFFER, 3);
  control.bind(GL_DRAW_INDIRECT_BUFFER);
  program_.use();
  vao_.bind();
  glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(kItemDrawOffset));
  glDisable(GL_CLIP_DISTANCE0);
}

void ItemBuffer::bindForLookup() const {
  id_.bindUnit(2);
  depth_.bindUnit(3);
}

}  // namespace hemirad
