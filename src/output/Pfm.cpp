#include "src/output/Pfm.h"

#include <fmt/format.h>

#include <bit>
#include <cstring>

namespace hemirad {

std::string encodePfm(const Image& image) {
  static_assert(std::endian::native == std::endian::little, "PFM's -1 scale promises little-endian floats");
  std::string out = fmt::format("PF\n{} {}\n-1.0\n", image.width, image.height);
  const std::size_t row = std::size_t(image.width) * 3;
  const std::size_t header = out.size();
  out.resize(header + row * std::size_t(image.height) * sizeof(float));
  for (int y = 0; y < image.height; ++y)  // PFM's first row is the image's bottom one
    std::memcpy(out.data() + header + std::size_t(y) * row * sizeof(float),
                image.rgb.data() + std::size_t(image.height - 1 - y) * row, row * sizeof(float));
  return out;
}

}  // namespace hemirad
