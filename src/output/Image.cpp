#include "src/output/Image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "src/base/Error.h"
#include "src/scene/Scene.h"  // kLuminanceWeights

namespace hemirad {

double exposureScale(const Image& image, double ev) {
  std::vector<float> lum;
  for (size_t i = 0; i + 2 < image.rgb.size(); i += 3) {
    float l = float(kLuminanceWeights[0]) * image.rgb[i] + float(kLuminanceWeights[1]) * image.rgb[i + 1] +
              float(kLuminanceWeights[2]) * image.rgb[i + 2];
    if (l > 0) lum.push_back(l);
  }
  double scale = 1.0;
  if (!lum.empty()) {
    auto k = lum.begin() + std::ptrdiff_t(0.95 * double(lum.size() - 1));
    std::nth_element(lum.begin(), k, lum.end());
    if (*k > 0) scale = 1.0 / *k;
  }
  return scale * std::exp2(ev);
}

namespace {
double pixelLuminance(const std::vector<float>& rgb, std::size_t p) {
  return kLuminanceWeights[0] * rgb[p] + kLuminanceWeights[1] * rgb[p + 1] + kLuminanceWeights[2] * rgb[p + 2];
}
}  // namespace

double meanLuminance(const Image& image) {
  double sum = 0;
  for (std::size_t p = 0; p + 2 < image.rgb.size(); p += 3) sum += pixelLuminance(image.rgb, p);
  return image.rgb.empty() ? 0.0 : sum / double(image.rgb.size() / 3);
}

double imageError(const Image& image, const Image& reference) {
  if (image.rgb.size() != reference.rgb.size()) throw std::invalid_argument("imageError: image sizes differ");
  double diff = 0, sum = 0;
  for (std::size_t p = 0; p + 2 < image.rgb.size(); p += 3) {
    diff += std::abs(pixelLuminance(image.rgb, p) - pixelLuminance(reference.rgb, p));
    sum += pixelLuminance(reference.rgb, p);
  }
  return sum > 0 ? diff / sum : 0.0;
}

double imageRmsError(const Image& image, const Image& reference) {
  if (image.rgb.size() != reference.rgb.size()) throw std::invalid_argument("imageRmsError: image sizes differ");
  double squares = 0, sum = 0;
  for (std::size_t p = 0; p + 2 < image.rgb.size(); p += 3) {
    const double d = pixelLuminance(image.rgb, p) - pixelLuminance(reference.rgb, p);
    squares += d * d;
    sum += pixelLuminance(reference.rgb, p);
  }
  const double pixels = double(image.rgb.size() / 3);
  return sum > 0 ? std::sqrt(squares / pixels) / (sum / pixels) : 0.0;
}

std::vector<unsigned char> toneMap(const Image& image, double scale) {
  std::vector<unsigned char> out(image.rgb.size());
  for (size_t i = 0; i < out.size(); ++i) {
    double v = std::clamp(double(image.rgb[i]) * scale, 0.0, 1.0);
    double s = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
    out[i] = static_cast<unsigned char>(std::lround(s * 255.0));
  }
  return out;
}

}  // namespace hemirad
