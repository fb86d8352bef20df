#include "src/output/Supersample.h"

#include <algorithm>
#include <cstddef>

#include <glm/gtc/matrix_transform.hpp>

namespace hemirad {

SupersampleGrid::SupersampleGrid(int samplesPerSide, int maxScale) {
  const int n = std::max(1, samplesPerSide);
  for (int s = std::clamp(maxScale, 1, n); s >= 1; --s)  // the largest framebuffer factor that divides N
    if (n % s == 0) {
      scale_ = s, passes_ = n / s;
      break;
    }
}

glm::mat4 SupersampleGrid::shift(int k, int w, int h) const {
  // Within a framebuffer pixel, sub-cell (i, j) of passes x passes has its centre (i + 1/2) /
  // passes - 1/2 pixels from the pixel's; moving the scene the other way samples it there.
  const double dx = (k % passes_ + 0.5) / passes_ - 0.5, dy = (k / passes_ + 0.5) / passes_ - 0.5;
  return glm::translate(glm::mat4(1.0f), glm::vec3(float(-2.0 * dx / w), float(-2.0 * dy / h), 0.0f));
}

void SupersampleGrid::accumulate(const std::vector<float>& rgba, int width, int height, int channels,
                                 std::vector<double>& sums) const {
  const int s = scale_;
  const std::size_t w = std::size_t(width) * s;
  sums.resize(std::size_t(width) * height * channels, 0.0);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double* out = &sums[(std::size_t(height - 1 - y) * width + x) * channels];  // GL rows go bottom-up
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const float* sample = &rgba[((std::size_t(y) * s + j) * w + std::size_t(x) * s + i) * 4];
          for (int c = 0; c < channels; ++c) out[c] += sample[c];
        }
    }
}

}  // namespace hemirad
