// Image files: what hemirad writes it reads back exactly, in bytes that depend on the image alone.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "src/base/Error.h"
#include "src/output/ImageFile.h"
#include "src/output/Pfm.h"
#include "tests/support/Files.h"

using namespace hemirad;

TEST_CASE("An EXR keeps every float bit, a PNG every 8-bit value, and the same image encodes to the same bytes",
          "[image]") {
  Image image{5, 3, {}};
  for (int i = 0; i < 45; ++i) image.rgb.push_back(std::ldexp(float(i * 7919 % 1013) + 0.123f, i % 40 - 30));
  const std::string exr = encodeExr(image);
  CHECK(encodeExr(image) == exr);
  CHECK(readImage(test::writeTempFile("bits.exr", exr)).rgb == image.rgb);
  std::vector<std::uint8_t> rgb(45);
  for (int i = 0; i < 45; ++i) rgb[std::size_t(i)] = std::uint8_t(i * 37 % 256);
  const Image png = readImage(test::writeTempFile("bytes.png", encodePng8(5, 3, rgb)));
  REQUIRE((png.width == 5 && png.height == 3));
  for (int i = 0; i < 45; ++i) CHECK(png.rgb[std::size_t(i)] == float(rgb[std::size_t(i)]) / 255);
}

TEST_CASE("A PFM reads as written in either byte order and channel count: its first row is the image's bottom",
          "[image]") {
  const Image image{2, 2, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}};
  CHECK(readImage(test::writeTempFile("little.pfm", encodePfm(image))).rgb == image.rgb);
  // Grey, big-endian (a positive scale): rows bottom up 0.5 0.25 / 2 4.
  std::string grey = "Pf\n2 2\n1.0\n";
  for (float v : {0.5f, 0.25f, 2.0f, 4.0f}) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    for (int shift = 24; shift >= 0; shift -= 8) grey += char((bits >> shift) & 0xff);
  }
  const std::vector<float> expected{2, 2, 2, 4, 4, 4, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f};
  CHECK(readImage(test::writeTempFile("grey.pfm", grey)).rgb == expected);
  const std::string cut = test::writeTempFile("cut.pfm", grey.substr(0, grey.size() - 1));
  CHECK_THROWS_WITH(readImage(cut), Catch::Contains(cut) && Catch::Contains("cut short"));
}
