#include "src/output/DrawBands.h"

#include <algorithm>
#include <chrono>

namespace hemirad {

int nextBandTiles(const BandPlan& plan, int tiles, double elapsed) {
  const double growth = elapsed > 0 ? std::min(plan.seconds / elapsed, double(plan.maxGrowth)) : plan.maxGrowth;
  return std::clamp(int(tiles * growth), 1, plan.maxTiles);
}

void drawInBands(const BandPlan& plan, int width, int height, const std::function<void(const gl::Rect&)>& drawBand) {
  using Clock = std::chrono::steady_clock;
  constexpr int T = BandPlan::kTile;
  const int across = (width + T - 1) / T, down = (height + T - 1) / T;
  int tiles = std::clamp(plan.firstTiles, 1, plan.maxTiles);
  for (int tx = 0, ty = 0; ty < down;) {
    gl::Rect band;
    int drawn;
    if (tx == 0 && tiles >= across) {  // whole rows of tiles
      const int rows = std::min(tiles / across, down - ty);
      band = {0, ty * T, width, std::min(rows * T, height - ty * T)};
      drawn = rows * across, ty += rows;
    } else {  // a run along the row
      drawn = std::min(tiles, across - tx);
      band = {tx * T, ty * T, std::min(drawn * T, width - tx * T), std::min(T, height - ty * T)};
      tx += drawn;
      if (tx == across) tx = 0, ++ty;
    }
    const Clock::time_point start = Clock::now();
    drawBand(band);
    gl::finish();
    tiles = nextBandTiles(plan, drawn, std::chrono::duration<double>(Clock::now() - start).count());
  }
}

}  // namespace hemirad
