#include "src/solver/ImportanceView.h"

#include <algorithm>
#include <cmath>

#include "gl/ReversedDepth.h"
#include "gl/Debug.h"
#include "gl/Shader.h"

namespace hemirad {

ImportanceView::ImportanceView(SolverState& state, int resolution)
    : state_(state),
      resolution_(resolution),
      mesh_(state.scene, state.atlas),
      view_(gl::renderProgram("camera.vert", "importance_view.frag")),
      update_(gl::computeProgram("importance_update.comp")),
      pixels_(GL_R32UI, state.atlas.width, state.atlas.height),
      direct_(GL_R32F, state.atlas.width, state.atlas.height) {
  const float zero = 0.0f;
  glClearTexImage(direct_.id(), 0, GL_RED, GL_FLOAT, &zero);
  glProgramUniform2i(update_.id(), update_.location("atlasSize"), state.atlas.width, state.atlas.height);
}

void ImportanceView::look(const Camera& camera, double aspect) {
  const int w = aspect >= 1 ? resolution_ : std::max(1, int(std::lround(resolution_ * aspect)));
  const int h = aspect >= 1 ? std::max(1, int(std::lround(resolution_ / aspect))) : resolution_;
  gl::Texture depth(GL_DEPTH_COMPONENT32F, w, h);
  gl::Framebuffer fbo;
  fbo.attach(GL_DEPTH_ATTACHMENT, depth);
  fbo.checkComplete("importance view");
  const GLuint zero = 0;
  glClearTexImage(pixels_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

  glm::mat4 vp = mesh_.viewProjection(camera, aspect);
  {
    gl::ReversedDepth depthPass(fbo);
    glViewport(0, 0, w, h);
    glDisable(GL_CULL_FACE);
    state_.bindScene();
    pixels_.bindImage(0, GL_READ_WRITE);
    view_.set("viewProjection", &vp[0][0]);
    view_.use();
    // Depth first, then count the pixels whose nearest surface each fragment is (same program,
    // so the depths match exactly).
    view_.set("countPixels", 0);
    mesh_.draw();
    glDepthFunc(GL_EQUAL);
    glDepthMask(GL_FALSE);
    view_.set("countPixels", 1);
    mesh_.draw();
    glDepthMask(GL_TRUE);
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

  update_.use();
  update_.set("viewPixels", float(w) * float(h));
  state_.radiosity.bindImage(0, GL_READ_WRITE);
  state_.deltaB.bindImage(1, GL_READ_WRITE);
  pixels_.bindImage(2, GL_READ_ONLY);
  direct_.bindImage(3, GL_READ_WRITE);
  gl::Program::dispatch(gl::groupsFor(unsigned(state_.atlas.width), 16), gl::groupsFor(unsigned(state_.atlas.height), 16));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  gl::checkErrors("importance view");
}

std::vector<float> ImportanceView::readDirect() const {
  std::vector<float> out(std::size_t(state_.atlas.width) * state_.atlas.height);
  direct_.read(GL_RED, GL_FLOAT, out.size() * sizeof(float), out.data());
  return out;
}

void ImportanceView::restoreDirect(const std::vector<float>& direct) { direct_.upload(GL_RED, GL_FLOAT, direct.data()); }

}  // namespace hemirad
