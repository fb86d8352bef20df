// Linear RGB images: exposure, the sRGB tone curve and image error. Files: ImageFile.h.
#pragma once
#include <string>
#include <vector>

namespace hemirad {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // linear, rows top to bottom
};

// Linear scale that maps the 95th-percentile luminance of lit pixels to 1, times 2^ev.
// Emitters (a few percent of pixels) clip to white; the rest keeps its range.
double exposureScale(const Image& image, double ev);
// Mean luminance (Rec. 709) of the pixels.
double meanLuminance(const Image& image);
// Mean |luminance difference| to `reference` over the pixels, relative to the reference's mean
// luminance: the view error of camera paths and experiments. Same sizes required.
double imageError(const Image& image, const Image& reference);
// RMS of the per-pixel luminance difference over the reference's mean luminance (issue 19's measure).
double imageRmsError(const Image& image, const Image& reference);
// 8-bit sRGB of the linear image times `scale`.
std::vector<unsigned char> toneMap(const Image& image, double scale);

}  // namespace hemirad
