// A camera render's framebuffer: RGBA32F colour and reversed depth, single- or multisampled. With
// N samples a pixel (`--msaa`), each framebuffer pixel's coverage is tested at the driver's N
// fixed sample positions while its fragment shader runs once per pixel and surface (at the
// surface's centroid in the pixel), as MSAA does: silhouettes and creases are resolved N times
// finer for the shading cost of one sample, so the per-pixel pass (seconds a draw) need not
// be supersampled as finely to get edges right.
#pragma once
#include <optional>
#include <vector>

#include "gl/Objects.h"

namespace hemirad {

class CameraTarget {
 public:
  CameraTarget(int width, int height, int samples);
  // The largest framebuffer scale (src/output/Supersample.h) whose `samples` samples a pixel
  // take no more memory than a single-sampled framebuffer of SupersampleGrid::kMaxScale: 256^2
  // at 8 x with 8 samples would be 671 MiB, 1,024^2 10.7 GiB.
  static int maxScale(int samples);
  // Colour (0, 0, 0, 1) and depth 0 (reversed depth: 0 is infinitely far), then bound.
  void clearAndBind();
  // The pixels (rows bottom-up), RGBA: multisampled ones the plain mean of their samples.
  void read(std::vector<float>& rgba);

 private:
  gl::Texture color_, depth_;
  gl::Framebuffer fbo_;
  std::optional<gl::Texture> resolved_;  // multisampled: the mean per pixel
  std::optional<gl::Program> resolve_;   // and shaders/resolve.comp, which writes it
};

}  // namespace hemirad
