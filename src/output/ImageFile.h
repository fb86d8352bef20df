// How images leave hemirad: float EXR (exact; OpenEXR), and PNG tone-mapped by exposure and the
// sRGB curve (stb_image_write). Both encoded in memory, then written atomically with every write
// checked (src/base/AtomicFile.h). Same image, same bytes: no time stamp in either header.
// Two small libraries rather than OpenImageIO: Debian's OpenImageIO loads ~260 shared libraries,
// 0.5 s at every start of every hemirad process.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "src/output/Image.h"

namespace hemirad {

std::string encodeExr(const Image& image);
std::string encodePng(const Image& image, double scale);
// An 8-bit RGB image's PNG (rows top to bottom), for what is tone-mapped already (screenshots).
std::string encodePng8(int width, int height, const std::vector<std::uint8_t>& rgb);
// --out's bytes: the linear EXR, or, for a name ending in .png, --image's tone mapping (8 bits
// cannot hold linear light).
std::string encodeRender(const std::string& path, const Image& image, double scale);
void writeExr(const std::string& path, const Image& image);
void writePng(const std::string& path, const Image& image, double scale);
// EXR, PFM, PNG, JPEG, HDR and the other formats stb_image reads, told apart by their bytes; RGB
// float: 8- and 16-bit values scaled to [0, 1] as stored (no sRGB decoding), floats as they are.
Image readImage(const std::string& path);

}  // namespace hemirad
