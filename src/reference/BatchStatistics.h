// The reference's estimate from independent batches: per pixel the mean of the batch means and
// its standard error s / sqrt(K) (s: the batch means' sample deviation, K batches), per channel
// and for luminance. Batches are added as they finish into running sums (in double, in batch
// order, so the result depends on the sums only): memory per pixel, whatever the batch count.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "src/output/Image.h"

namespace hemirad {

struct ReferenceEstimate {
  Image mean;                          // B per pixel
  Image standardError;                 // per channel
  std::vector<double> luminanceError;  // the standard error of each pixel's luminance
  double meanLuminance = 0;            // over the pixels
  double meanStandardError = 0;        // of luminance, over the pixels
};

class BatchStatistics {
 public:
  BatchStatistics(int width, int height, unsigned samplesPerBatch);
  void add(const std::vector<glm::vec4>& sums);  // one batch's per-pixel sums of its paths
  ReferenceEstimate estimate() const;            // needs two batches
  unsigned batches() const { return batches_; }

 private:
  int width_, height_;
  double samplesPerBatch_;
  unsigned batches_ = 0;
  std::vector<glm::dvec4> sum_, squares_;  // of the batch means: rgb, and luminance in w
};

}  // namespace hemirad
