#include "src/output/ImageFile.h"

#include <OpenImageIO/imageio.h>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"

namespace hemirad {

namespace {
// The format is chosen by name, not by the path's extension: /dev/stdout or a FIFO has none.
void writeWith(const std::string& path, const char* format, const OIIO::ImageSpec& spec, const void* pixels) {
  writeAtomically(path, [&](const std::string& tmp) {
    auto out = OIIO::ImageOutput::create(format);
    if (!out) fail("{}: no {} image writer", path, format);
    if (!out->open(tmp, spec) || !out->write_image(spec.format, pixels) || !out->close())
      fail("{}: cannot write: {}", path, out->geterror());
  });
}
}  // namespace

void writeExr(const std::string& path, const Image& image) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  writeWith(path, "openexr", spec, image.rgb.data());
}

void writePng(const std::string& path, const Image& image, double scale) {
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  std::vector<unsigned char> pixels = toneMap(image, scale);
  writeWith(path, "png", spec, pixels.data());
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
