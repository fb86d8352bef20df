// Camera views use reversed Z: depth = near / (distance along the view axis), 1 at the near plane
// and 0 at infinity, in a float depth buffer cleared to 0 and tested with GL_GREATER. A float's
// spacing shrinks with its value, so the relative precision is ~1e-7 at every distance: a light
// 0.5 mm below a ceiling 1 m away wins its pixels (a [-1, 1] depth range loses that to rounding).
#pragma once
#include "gl/Objects.h"

namespace hemirad::gl {

// For its lifetime: [0, 1] clip depth, the depth test on with GL_GREATER, `target` bound and its
// depth cleared to 0. Restores GL's defaults ([-1, 1], GL_LESS) after, which the item buffer uses.
class ReversedDepth {
 public:
  explicit ReversedDepth(const Framebuffer& target);
  ~ReversedDepth();
  ReversedDepth(const ReversedDepth&) = delete;
  ReversedDepth& operator=(const ReversedDepth&) = delete;
};

}  // namespace hemirad::gl
