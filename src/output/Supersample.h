// Anti-aliasing beyond one framebuffer: `--supersample N` samples a pixel on the regular N x N
// grid (centres at (i + 1/2) / N), which the box filter averages to approach the pixel's integral
// (what `hemirad reference` estimates). A framebuffer of `scale` x the image holds scale^2 of
// them; `passes` x `passes` draws, each shifted by a fraction of a framebuffer pixel, give the
// rest, so N = 32 costs 16 draws at 8 x, not a 32 x framebuffer (8,192^2 at 256^2).
#pragma once
#include <vector>

#include <glm/glm.hpp>

namespace hemirad {

class SupersampleGrid {
 public:
  // A single-sampled framebuffer of at most 8 x the image a side (a multisampled one of cameraPlan,
  // src/output/CameraTarget.h, is bounded by its samples instead).
  static constexpr int kMaxScale = 8;
  // `maxScale`: the largest framebuffer factor allowed (a multisampled render takes N itself).
  explicit SupersampleGrid(int samplesPerSide, int maxScale = kMaxScale);
  int scale() const { return scale_; }
  int draws() const { return passes_ * passes_; }
  // Draw k's (0 <= k < draws()) clip-space shift, to multiply the view-projection by on the left,
  // for a framebuffer of w x h.
  glm::mat4 shift(int k, int w, int h) const;
  // Adds a w x h RGBA framebuffer (rows bottom-up) into `sums`, per image pixel (rows top-down)
  // and channel, `channels` (3 or 4) of each sample's RGBA.
  void accumulate(const std::vector<float>& rgba, int width, int height, int channels, std::vector<double>& sums) const;

 private:
  int scale_ = 1, passes_ = 1;
};

}  // namespace hemirad
