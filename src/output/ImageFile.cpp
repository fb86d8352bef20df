#include "src/output/ImageFile.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStdIO.h>
#include <ImfVersion.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Pfm.h"

namespace hemirad {

namespace {
// The three float channels of `rgb` (rows top to bottom) as OpenEXR slices.
Imf::FrameBuffer rgbSlices(float* rgb, int width) {
  Imf::FrameBuffer frame;
  const std::size_t pixel = 3 * sizeof(float), row = pixel * std::size_t(width);
  const char* names[3] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgb + c), pixel, row));
  return frame;
}

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), std::size_t(size));
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("{}: cannot read image: no such file or no permission", path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// `bytes`, the file's, decoded in memory (the file was read once, to tell its format).
Image readExr(const std::string& path, const std::string& bytes) {
  try {
    Imf::StdISStream stream;
    stream.str(bytes);
    Imf::InputFile in(stream);
    const Imath::Box2i window = in.header().dataWindow();
    Image img{window.max.x - window.min.x + 1, window.max.y - window.min.y + 1, {}};
    img.rgb.assign(std::size_t(img.width) * img.height * 3, 0.0f);
    // The slices' origin is the data window's corner (OpenEXR addresses them absolutely).
    float* origin = img.rgb.data() - (std::ptrdiff_t(window.min.y) * img.width + window.min.x) * 3;
    in.setFrameBuffer(rgbSlices(origin, img.width));
    in.readPixels(window.min.y, window.max.y);
    return img;
  } catch (const std::exception& e) {
    fail("{}: cannot read EXR image: {}", path, e.what());
  }
}

Image readStb(const std::string& path, const std::string& bytes) {
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = int(std::min<std::size_t>(bytes.size(), INT32_MAX));
  int w = 0, h = 0, channels = 0;
  Image img;
  auto fill = [&](auto* pixels, float maxValue) {
    if (!pixels) fail("{}: cannot read image: {}", path, stbi_failure_reason());
    img = {w, h, std::vector<float>(std::size_t(w) * h * 3)};
    for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = float(pixels[i]) / maxValue;
    stbi_image_free(pixels);
  };
  if (stbi_is_hdr_from_memory(data, size))
    fill(stbi_loadf_from_memory(data, size, &w, &h, &channels, 3), 1.0f);
  else if (stbi_is_16_bit_from_memory(data, size))
    fill(stbi_load_16_from_memory(data, size, &w, &h, &channels, 3), 65535.0f);
  else
    fill(stbi_load_from_memory(data, size, &w, &h, &channels, 3), 255.0f);
  return img;
}
}  // namespace

std::string encodeExr(const Image& image) {
  Imf::Header header(image.width, image.height);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  Imf::StdOSStream memory;  // in memory: nothing reaches the disk unchecked (AtomicFile does that)
  try {
    Imf::OutputFile out(memory, header);
    out.setFrameBuffer(rgbSlices(const_cast<float*>(image.rgb.data()), image.width));
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    fail("cannot encode EXR: {}", e.what());
  }
  return memory.str();
}

std::string encodePng8(int width, int height, const std::vector<std::uint8_t>& rgb) {
  std::string bytes;
  if (!stbi_write_png_to_func(appendBytes, &bytes, width, height, 3, rgb.data(), width * 3))
    fail("cannot encode a {} x {} PNG", width, height);
  return bytes;
}

std::string encodePng(const Image& image, double scale) {
  return encodePng8(image.width, image.height, toneMap(image, scale));
}

std::string encodeRender(const std::string& path, const Image& image, double scale) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".png" ? encodePng(image, scale) : encodeExr(image);
}

void writeExr(const std::string& path, const Image& image) { writeFileBytes(path, encodeExr(image)); }

void writePng(const std::string& path, const Image& image, double scale) {
  writeFileBytes(path, encodePng(image, scale));
}

Image readImage(const std::string& path) {
  const std::string bytes = readBytes(path);
  if (bytes.size() >= 4 && Imf::isImfMagic(bytes.data())) return readExr(path, bytes);
  if (bytes.size() >= 3 && bytes[0] == 'P' && (bytes[1] == 'F' || bytes[1] == 'f') && std::isspace(bytes[2]))
    return decodePfm(bytes, path);
  return readStb(path, bytes);
}

}  // namespace hemirad
