// How images leave hemirad: float EXR (exact), and PNG tone-mapped by exposure and the sRGB
// curve. Both through OpenImageIO, written atomically.
#pragma once
#include <string>

#include "src/output/Image.h"

namespace hemirad {

void writeExr(const std::string& path, const Image& image);
void writePng(const std::string& path, const Image& image, double scale);
Image readImage(const std::string& path);  // any format OpenImageIO reads; RGB float

}  // namespace hemirad
