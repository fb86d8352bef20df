// `hemirad compare`'s table (issue 31): the relative luminance error (L_A - L_B) / L_B of image A
// against image B per region of the view (PixelRegions.h): surface interiors (>= 4 px from any
// edge), the 1-px edge band, the 1, 2 and 3 px bands from a concave crease (room corners), the
// surfaces 1-3 px beside a light in their plane (the ceiling around it), each object and the
// whole image. Pixels that see nothing or where B is black are left out.
#pragma once
#include <string>
#include <vector>

#include "src/output/Image.h"
#include "src/reference/PixelRegions.h"

namespace hemirad {

struct ErrorRow {
  std::string region;
  std::size_t pixels = 0;
  double meanAbsolute = 0, p95Absolute = 0, bias = 0;  // mean |e|, its 95th percentile, mean e
  double noise = -1;  // mean of B's standard error / L_B (with --stderr); -1: not given
};

// `standardError` may be empty (no noise column).
std::vector<ErrorRow> errorTable(const Scene& scene, const PixelRegions& regions, const Image& a, const Image& b,
                                 const Image& standardError);
std::string markdown(const std::vector<ErrorRow>& rows);
// Per pixel the signed relative error: red where A is brighter, blue where darker, full at
// +-`range`; white where they agree, black where a pixel is left out.
Image errorMap(const PixelRegions& regions, const Image& a, const Image& b, double range);

}  // namespace hemirad
