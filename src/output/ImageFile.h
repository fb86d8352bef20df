// How images leave hemirad: float EXR (exact), and PNG tone-mapped by exposure and the sRGB
// curve. Both encoded in memory by OpenImageIO, then written atomically with every write
// checked (src/base/AtomicFile.h). Same image, same bytes: no time stamp in either header.
#pragma once
#include <string>

#include "src/output/Image.h"

namespace hemirad {

std::string encodeExr(const Image& image);
std::string encodePng(const Image& image, double scale);
// --out's bytes: the linear EXR, or, for a name ending in .png, --image's tone mapping (8 bits
// cannot hold linear light).
std::string encodeRender(const std::string& path, const Image& image, double scale);
void writeExr(const std::string& path, const Image& image);
void writePng(const std::string& path, const Image& image, double scale);
Image readImage(const std::string& path);  // any format OpenImageIO reads; RGB float

}  // namespace hemirad
