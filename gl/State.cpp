#include "gl/State.h"

#include "gl/Objects.h"

namespace hemirad::gl {

namespace {
void enable(GLenum cap, bool on) { on ? glEnable(cap) : glDisable(cap); }
}  // namespace

void RasterState::apply() const {
  glViewport(0, 0, width, height);
  enable(GL_DEPTH_TEST, depthTest);
  glDepthFunc(GLenum(depthFunc));
  glClipControl(GL_LOWER_LEFT, depthRange == DepthRange::Reversed ? GL_ZERO_TO_ONE : GL_NEGATIVE_ONE_TO_ONE);
  glDepthMask(depthWrite ? GL_TRUE : GL_FALSE);
  enable(GL_CULL_FACE, cullFaces);
  enable(GL_CLIP_DISTANCE0, clipDistance0);
  enable(GL_BLEND, additiveBlend);
  if (additiveBlend) glBlendFunc(GL_ONE, GL_ONE);
  enable(GL_SCISSOR_TEST, scissor.has_value());
  if (scissor) glScissor(scissor->x, scissor->y, scissor->width, scissor->height);
}

void barrier(Barrier bits) { glMemoryBarrier(GLbitfield(bits)); }

void drawTriangles(std::size_t vertices, int instances) {
  if (instances == 1)
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(vertices));
  else
    glDrawArraysInstanced(GL_TRIANGLES, 0, GLsizei(vertices), instances);
}

void drawIndexedTriangles(std::size_t indices, int instances) {
  glDrawElementsInstanced(GL_TRIANGLES, GLsizei(indices), GL_UNSIGNED_INT, nullptr, instances);
}

void drawIndexedIndirect(const Buffer& commands, std::size_t count) {
  commands.bind(GL_DRAW_INDIRECT_BUFFER);
  glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, nullptr, GLsizei(count), 0);
}

void finish() { glFinish(); }

}  // namespace hemirad::gl
