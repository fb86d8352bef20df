// A camera render's framebuffer: RGBA32F colour and reversed depth, single- or multisampled. With
// N samples a pixel (`--msaa`), each framebuffer pixel's coverage is tested at the driver's N
// fixed sample positions while its fragment shader runs once per pixel and surface (at the
// surface's centroid in the pixel), as MSAA does: silhouettes and creases are resolved N times
// finer for the shading cost of one sample, so the per-pixel pass (seconds a draw) need not
// be supersampled as finely to get edges right.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "gl/Objects.h"

namespace hemirad {

// How a width x height image of N x N cells (`--supersample N`) with M samples a cell is drawn.
// MSAA's samples span their framebuffer pixel, so shifting the scene by a fraction of a pixel
// (src/output/Supersample.h's extra draws) would move some of them past it and widen each image
// pixel's box (measured on the H100: the 1-px edge band stayed near 2 % from 4 x 4 to 32 x 32
// cells). So M > 1 only in one framebuffer of N x the image, of at most kMaxSamples samples and
// the GPU's texture size; past that, one sample a cell and the grid's shifted draws.
struct CameraPlan {
  static constexpr std::size_t kMaxSamples = std::size_t(1) << 26;  // 1.3 GiB: RGBA32F + depth
  int scale = 1, samples = 1;
};
CameraPlan cameraPlan(int width, int height, int supersample, int samples, int maxTextureSize);

class CameraTarget {
 public:
  CameraTarget(int width, int height, int samples);
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
