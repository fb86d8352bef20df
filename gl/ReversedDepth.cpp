#include "gl/ReversedDepth.h"

namespace hemirad::gl {

ReversedDepth::ReversedDepth(const Framebuffer& target) {
  const float zero = 0.0f;
  glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &zero);
  target.bind();
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
}

ReversedDepth::~ReversedDepth() {
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDepthFunc(GL_LESS);
}

}  // namespace hemirad::gl
