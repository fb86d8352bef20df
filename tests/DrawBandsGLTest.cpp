// The per-pixel pass is drawn in bands of 64-pixel tiles sized from their time
// (src/output/DrawBands.h), so no draw runs long enough for a GPU driver to drop it: the bands
// cover the frame once whatever their sizes, shrink after a slow band, and the image is the same
// to the bit however it is split.
#include <catch2/catch.hpp>

#include "src/output/DrawBands.h"
#include "src/output/Renderer.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/CornellView.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("A band's successor is sized to the plan's seconds, grows at most maxGrowth and stays within maxTiles",
          "[camera]") {
  const BandPlan plan{.seconds = 0.25, .firstTiles = 4, .maxTiles = 100, .maxGrowth = 4};
  CHECK(nextBandTiles(plan, 40, 1.0) == 10);    // 4 x too slow: a quarter of the tiles
  CHECK(nextBandTiles(plan, 40, 0.125) == 80);  // twice too fast: twice the tiles
  CHECK(nextBandTiles(plan, 20, 0.001) == 80);  // nearly free: 4 x at most
  CHECK(nextBandTiles(plan, 40, 0.0) == 100);   // maxTiles at most
  CHECK(nextBandTiles(plan, 1, 60.0) == 1);     // a tile at least
}

TEST_CASE("Bands cover every pixel of the frame once, on 64-pixel tiles, however fast they run", "[gl][camera]") {
  test::backend();
  const int W = 300, H = 200;                 // 5 x 4 tiles, the last column and row partial
  for (const double seconds : {1e-9, 1e9}) {  // every band too slow (a tile each) or too fast (growing to the cap)
    const BandPlan plan{.seconds = seconds, .firstTiles = 3, .maxTiles = 12};
    std::vector<int> covered(W * H, 0);
    std::vector<gl::Rect> bands;
    drawInBands(plan, W, H, [&](const gl::Rect& b) {
      bands.push_back(b);
      for (int y = b.y; y < b.y + b.height; ++y)
        for (int x = b.x; x < b.x + b.width; ++x) ++covered[y * W + x];
    });
    INFO("seconds " << seconds << ", " << bands.size() << " bands");
    CHECK(std::count(covered.begin(), covered.end(), 1) == W * H);
    for (const gl::Rect& b : bands) {
      CHECK(b.x % BandPlan::kTile == 0);
      CHECK(b.y % BandPlan::kTile == 0);
      CHECK(b.width * b.height <= 12 * BandPlan::kTile * BandPlan::kTile);
    }
    // The first 3 tiles, then a tile each (17); or then the rest of row 0 (2 tiles) and whole
    // rows of 5 tiles (2 rows, then the last).
    CHECK(bands.size() == (seconds < 1 ? 18u : 4u));
  }
}

TEST_CASE(
    "A per-pixel direct render with the near gather is the same to the bit in one band or in bands of a tile, clears "
    "whole",
    "[gl][camera][direct][heavy]") {
  test::backend();
  const test::CornellView v;
  const NearGather gather(v.scene, v.atlas, v.sent);
  const Camera& camera = v.camera;
  Renderer renderer(v.state);
  renderer.show(v.sent);
  renderer.usePerPixelDirect(v.light, &gather);
  renderer.setBandPlan({.firstTiles = 100, .maxTiles = 100});  // 96^2 pixels: 4 tiles in one band
  const Image whole = renderer.render(camera, 24, 24, 4);
  renderer.setBandPlan({.seconds = 1e-9, .firstTiles = 1, .maxTiles = 1});  // 4 bands
  const Image tiles = renderer.render(camera, 24, 24, 4);
  renderer.setBandPlan({.firstTiles = 100, .maxTiles = 100});  // its clears are whole, not the last band's
  const Image after = renderer.render(camera, 24, 24, 4);
  double sum = 0;
  for (float v : whole.rgb) sum += v;
  REQUIRE(sum > 0);
  CHECK(tiles.rgb == whole.rgb);
  CHECK(after.rgb == whole.rgb);
}
