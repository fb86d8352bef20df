#include "src/solver/ImportanceView.h"

#include <algorithm>
#include <cmath>

#include "gl/Debug.h"
#include "gl/State.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

ImportanceView::ImportanceView(SolverState& state, int resolution)
    : state_(state),
      resolution_(resolution),
      mesh_(state.scene, state.atlas),
      view_(renderProgram("camera.vert", "importance_view.frag")),
      update_(computeProgram("importance_update.comp")),
      pixels_(GL_R32UI, state.atlas.width, state.atlas.height),
      direct_(GL_R32F, state.atlas.width, state.atlas.height) {
  direct_.clear(0.0f);
  update_.set("atlasSize", state.atlas.width, state.atlas.height);
}

bool ImportanceView::look(const Camera& camera, double aspect) {
  if (looked_ && looked_->first == camera && looked_->second == aspect) return false;
  looked_ = {camera, aspect};
  const int w = aspect >= 1 ? resolution_ : std::max(1, int(std::lround(resolution_ * aspect)));
  const int h = aspect >= 1 ? std::max(1, int(std::lround(resolution_ / aspect))) : resolution_;
  gl::Texture depth(GL_DEPTH_COMPONENT32F, w, h);
  gl::Framebuffer fbo;
  fbo.attach(GL_DEPTH_ATTACHMENT, depth);
  fbo.checkComplete("importance view");
  fbo.clearDepth(0.0f);  // reversed depth: 0 is infinitely far
  pixels_.clear(0u);

  glm::mat4 vp = mesh_.viewProjection(camera, aspect);
  fbo.bind();
  state_.bindScene();
  pixels_.bindImage(slot::IMAGE_VIEW_PIXELS, GL_READ_WRITE);
  view_.set("viewProjection", &vp[0][0]);
  view_.use();
  // Depth first, then count the pixels whose nearest surface each fragment is (same program,
  // so the depths match exactly).
  gl::cameraView(w, h).apply();
  view_.set("countPixels", 0);
  mesh_.draw();
  gl::RasterState equal = gl::cameraView(w, h);
  equal.depthFunc = gl::DepthFunc::Equal;
  equal.depthWrite = false;
  equal.apply();
  view_.set("countPixels", 1);
  mesh_.draw();
  gl::barrier(gl::Barrier::Image);

  update_.use();
  update_.set("viewPixels", float(w) * float(h));
  state_.radiosity.bindImage(slot::IMAGE_RADIOSITY, GL_READ_WRITE);
  state_.deltaB.bindImage(slot::IMAGE_DELTA_B, GL_READ_WRITE);
  pixels_.bindImage(slot::IMAGE_VIEW_PIXELS, GL_READ_ONLY);
  direct_.bindImage(slot::IMAGE_DIRECT, GL_READ_WRITE);
  gl::Program::dispatch(gl::groupsFor(unsigned(state_.atlas.width), 16),
                        gl::groupsFor(unsigned(state_.atlas.height), 16));
  gl::barrier(gl::Barrier::Image | gl::Barrier::TextureFetch | gl::Barrier::Storage);
  gl::checkErrors("importance view");
  return true;
}

std::vector<float> ImportanceView::readDirect() const {
  std::vector<float> out(std::size_t(state_.atlas.width) * state_.atlas.height);
  direct_.read(GL_RED, GL_FLOAT, out.size() * sizeof(float), out.data());
  return out;
}

void ImportanceView::restoreDirect(const std::vector<float>& direct) {
  direct_.upload(GL_RED, GL_FLOAT, direct.data());
}

}  // namespace hemirad
