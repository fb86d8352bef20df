#include "src/output/ImageFile.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <ctime>
#include <filesystem>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"

namespace hemirad {

namespace {
// The file's bytes, encoded in memory: the format is chosen by name, not by a path's extension
// (/dev/stdout or a FIFO has none), and nothing reaches the disk unchecked.
std::string encode(const char* format, const OIIO::ImageSpec& spec, const void* pixels) {
  std::vector<unsigned char> bytes;
  OIIO::Filesystem::IOVecOutput memory(bytes);
  auto out = OIIO::ImageOutput::create(format);
  if (!out || !out->supports("ioproxy")) fail("no {} image writer that writes to memory", format);
  if (!out->set_ioproxy(&memory) || !out->open(std::string("memory.") + format, spec) ||
      !out->write_image(spec.format, pixels) || !out->close())
    fail("cannot encode {}: {}", format, out->geterror());
  return {bytes.begin(), bytes.end()};
}
}  // namespace

// OpenEXR stamps the write time into the header unless told a time: none, or the reproducible
// build convention's SOURCE_DATE_EPOCH, so the same image gives the same bytes.
static std::string exrDateTime() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch || !*epoch) return "";
  const std::time_t t = std::time_t(std::strtoll(epoch, nullptr, 10));
  std::tm utc{};
  gmtime_r(&t, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y:%m:%d %H:%M:%S", &utc);
  return text;
}

std::string encodeExr(const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  spec.attribute("DateTime", exrDateTime());
  return encode("openexr", spec, image.rgb.data());
}

std::string encodePng(const Image& image, double scale) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> pixels = toneMap(image, scale);
  return encode("png", spec, pixels.data());
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
  auto in = OIIO::ImageInput::open(path);
  if (!in) fail("{}: cannot read image: {}", path, OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  Image img{spec.width, spec.height, std::vector<float>(size_t(spec.width) * spec.height * 3)};
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, img.rgb.data())) fail("{}: {}", path, in->geterror());
  return img;
}

}  // namespace hemirad
