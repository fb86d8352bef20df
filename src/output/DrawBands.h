// A heavy full-frame draw split into bands of 64 x 64-pixel tiles, each finished before the next
// and sized from the last one's time. The NVIDIA driver drops a draw that runs for seconds: on an
// H100 the per-pixel pass with the near gather at 2,048^2 ran 11.2 s as one draw and read back as
// zeros, alpha too, with no GL error, while draws of 3.4 s and bands of 0.1-3 s were kept
// (docs/adaptive.md). Each pixel lies in one band, and bands follow llvmpipe's 64-pixel tiles
// (rows of 32 changed its pixels in the fourth digit; tiles leave them to the bit), so the image
// does not depend on the split.
#pragma once
#include <functional>

#include "gl/State.h"

namespace hemirad {

struct BandPlan {
  static constexpr int kTile = 64;  // pixels a side
  double seconds = 0.25;            // a band's aim; the driver's limit lies between 3.4 and 11 s
  int firstTiles = 4;               // the first band, before any time is known
  int maxTiles = 64;                // no band larger, however fast the last (a cheap band of sky
                                    // can come before an expensive one): 262,144 pixels
  int maxGrowth = 4;                // nor more than this many times the last
};

// The next band's tiles after one of `tiles` took `elapsed` seconds: sized to take plan.seconds
// at the same cost a tile, within [1, plan.maxTiles].
int nextBandTiles(const BandPlan& plan, int tiles, double elapsed);

// Calls drawBand(rectangle) for bands covering a width x height frame once, finishing the GPU's
// work after each: whole rows of tiles while the band takes a row or more, else runs of tiles
// along one row.
void drawInBands(const BandPlan& plan, int width, int height, const std::function<void(const gl::Rect&)>& drawBand);

}  // namespace hemirad
