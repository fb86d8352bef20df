#include "src/output/Pfm.h"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <sstream>

#include "src/base/Error.h"

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

Image decodePfm(const std::string& bytes, const std::string& path) {
  std::istringstream header(bytes);
  std::string magic;
  long long width = 0, height = 0;
  double scale = 0;
  header >> magic >> width >> height >> scale;
  if (!header || (magic != "PF" && magic != "Pf") || width <= 0 || height <= 0 || width > 1 << 16 || height > 1 << 16 ||
      scale == 0)
    fail("{}: not a PFM image (a 'PF' or 'Pf' header, a size and a nonzero scale)", path);
  const int channels = magic == "PF" ? 3 : 1;
  const std::size_t start = std::size_t(header.tellg()) + 1;  // one whitespace byte ends the header
  const std::size_t row = std::size_t(width) * channels, floats = row * std::size_t(height);
  if (bytes.size() < start + floats * sizeof(float))
    fail("{}: PFM image cut short: {} x {} needs {} bytes of pixels", path, width, height, floats * sizeof(float));
  std::vector<float> data(floats);
  std::memcpy(data.data(), bytes.data() + start, floats * sizeof(float));
  if ((scale < 0) != (std::endian::native == std::endian::little))
    for (float& f : data) f = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(f)));
  Image image{int(width), int(height), std::vector<float>(std::size_t(width) * height * 3)};
  for (long long y = 0; y < height; ++y)  // bottom row first
    for (long long x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        image.rgb[(std::size_t(height - 1 - y) * width + x) * 3 + c] =
            data[std::size_t(y) * row + std::size_t(x) * channels + (channels == 3 ? c : 0)];
  return image;
}

}  // namespace hemirad
