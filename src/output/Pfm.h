// Portable float map (PFM): linear RGB floats with no library behind them, the image format of
// the lean hemirad-bench (its `reference` subcommand on GPU machines without image libraries).
// hemirad compare reads it as it reads EXR (src/output/ImageFile.h).
#pragma once
#include <string>

#include "src/output/Image.h"

namespace hemirad {

// The file's bytes: "PF", the size, -1 (little-endian), then the rows bottom to top.
std::string encodePfm(const Image& image);
// A PFM file's image ("PF" RGB or "Pf" grey, either byte order); errors name `path`.
Image decodePfm(const std::string& bytes, const std::string& path);

}  // namespace hemirad
