// The reference's estimate from independent batches: per pixel the mean of the batch means and
// its standard error s / sqrt(K) (s: the batch means' sample deviation, K batches), per channel
// and for luminance. Summed in double in batch order, so the result depends on the sums only.
#pragma once
#include "src/output/Image.h"
#include "src/reference/PathTracer.h"

namespace hemirad {

struct ReferenceEstimate {
  Image mean;                         // B per pixel
  Image standardError;                // per channel
  std::vector<double> luminanceError;  // the standard error of each pixel's luminance
  double meanLuminance = 0;            // over the pixels
  double meanStandardError = 0;        // of luminance, over the pixels
};

ReferenceEstimate estimate(const BatchSums& sums);

}  // namespace hemirad
