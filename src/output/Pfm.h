// Portable float map (PFM): linear RGB floats with no library behind them, the image format of
// the lean hemirad-bench (its `reference` subcommand on GPU machines without OpenImageIO).
// OpenImageIO and oiiotool read it (`oiiotool ref.pfm -o ref.exr` for hemirad compare).
#pragma once
#include <string>

#include "src/output/Image.h"

namespace hemirad {

// The file's bytes: "PF", the size, -1 (little-endian), then the rows bottom to top.
std::string encodePfm(const Image& image);

}  // namespace hemirad
