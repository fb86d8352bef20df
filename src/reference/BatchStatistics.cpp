#include "src/reference/BatchStatistics.h"

#include <cmath>

#include "src/scene/Scene.h"

namespace hemirad {

ReferenceEstimate estimate(const BatchSums& s) {
  const std::size_t pixels = std::size_t(s.width) * s.height;
  const double K = s.batches, n = s.samplesPerBatch;
  ReferenceEstimate e{{s.width, s.height, std::vector<float>(pixels * 3)},
                      {s.width, s.height, std::vector<float>(pixels * 3)},
                      std::vector<double>(pixels)};
  for (std::size_t p = 0; p < pixels; ++p) {
    glm::dvec3 sum(0.0), squares(0.0);
    double lum = 0, lumSquares = 0;
    for (unsigned b = 0; b < s.batches; ++b) {
      const glm::dvec3 m = glm::dvec3(s.sums[b * pixels + p]) / n;  // the batch's mean
      sum += m, squares += m * m;
      lum += luminance(m), lumSquares += luminance(m) * luminance(m);
    }
    const glm::dvec3 mean = sum / K;
    // Sample variance of the batch means over K: the variance of their mean.
    const glm::dvec3 var = glm::max((squares - K * mean * mean) / (K - 1), glm::dvec3(0.0)) / K;
    const double lumMean = lum / K, lumVar = std::max((lumSquares - K * lumMean * lumMean) / (K - 1), 0.0) / K;
    for (int c = 0; c < 3; ++c) {
      e.mean.rgb[3 * p + c] = float(mean[c]);
      e.standardError.rgb[3 * p + c] = float(std::sqrt(var[c]));
    }
    e.luminanceError[p] = std::sqrt(lumVar);
    e.meanLuminance += lumMean / double(pixels);
    e.meanStandardError += e.luminanceError[p] / double(pixels);
  }
  return e;
}

}  // namespace hemirad
