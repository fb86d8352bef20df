#include "src/reference/BatchStatistics.h"

#include <cmath>

#include "src/scene/Scene.h"

namespace hemirad {

BatchStatistics::BatchStatistics(int width, int height, unsigned samplesPerBatch)
    : width_(width),
      height_(height),
      samplesPerBatch_(samplesPerBatch),
      sum_(std::size_t(width) * height, glm::dvec4(0.0)),
      squares_(sum_) {}

void BatchStatistics::add(const std::vector<glm::vec4>& sums) {
  for (std::size_t p = 0; p < sum_.size(); ++p) {
    const glm::dvec3 m = glm::dvec3(sums[p]) / samplesPerBatch_;  // the batch's mean
    const glm::dvec4 v(m, luminance(m));
    sum_[p] += v, squares_[p] += v * v;
  }
  ++batches_;
}

ReferenceEstimate BatchStatistics::estimate() const {
  const std::size_t pixels = sum_.size();
  const double K = batches_;
  ReferenceEstimate e{{width_, height_, std::vector<float>(pixels * 3)},
                      {width_, height_, std::vector<float>(pixels * 3)},
                      std::vector<double>(pixels)};
  for (std::size_t p = 0; p < pixels; ++p) {
    const glm::dvec4 mean = sum_[p] / K;
    // The batch means' sample variance over K: the variance of their mean.
    const glm::dvec4 var = glm::max((squares_[p] - K * mean * mean) / (K - 1), glm::dvec4(0.0)) / K;
    for (int c = 0; c < 3; ++c) {
      e.mean.rgb[3 * p + c] = float(mean[c]);
      e.standardError.rgb[3 * p + c] = float(std::sqrt(var[c]));
    }
    e.luminanceError[p] = std::sqrt(var.w);
    e.meanLuminance += mean.w / double(pixels);
    e.meanStandardError += e.luminanceError[p] / double(pixels);
  }
  return e;
}

}  // namespace hemirad
