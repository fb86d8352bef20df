// The per-pixel pass in shares (src/output/DirectShares.h): every emitter piece and gather block
// lies in one draw, and a lamp of many pieces behind an occluder, whose walks to all of them pass
// llvmpipe's loop limit in one draw, is drawn a share of the pieces a draw and still exact.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "cpu/ExactFormFactor.h"
#include "gl/Backend.h"
#include "src/output/DirectShares.h"
#include "src/output/Renderer.h"
#include "src/solver/Bvh.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE(
    "Shares put every strip of the emitter pieces and every gather block in one draw, never both in one, whole pieces "
    "while there are as many pieces as draws, as even as whole units allow",
    "[cpu]") {
  CHECK(directShares({1, 1}, 7, 8, 300).size() == 1);  // one draw of all
  CHECK(directShares({1, 1}, 7, 8, 300).front().stripsEnd == 56);
  const std::tuple<SharePlan, unsigned, unsigned> cases[] = {{{1, 16}, 7, 300}, {{4, 4}, 7, 300}, {{16, 16}, 3, 5},
                                                             {{64, 64}, 0, 9},  {{5, 1}, 12, 0},  {{1024, 1}, 2, 0}};
  for (const auto& [plan, pieces, blocks] : cases) {
    const unsigned grid = 8, strips = pieces * grid;
    const std::vector<DirectShare> shares = directShares(plan, pieces, grid, blocks);
    std::vector<int> strip(strips), block(blocks);
    unsigned most = 0, least = ~0u;
    for (const DirectShare& s : shares) {
      CHECK((s.stripsFirst == s.stripsEnd) != (s.blocksFirst == s.blocksEnd));  // one kind, not empty
      for (unsigned p = s.stripsFirst; p < s.stripsEnd; ++p) ++strip[p];
      for (unsigned b = s.blocksFirst; b < s.blocksEnd; ++b) ++block[b];
      if (s.stripsEnd == s.stripsFirst) continue;
      if (plan.direct <= pieces) CHECK((s.stripsFirst % grid == 0 && s.stripsEnd % grid == 0));  // whole pieces
      const unsigned units = plan.direct <= pieces ? (s.stripsEnd - s.stripsFirst) / grid : s.stripsEnd - s.stripsFirst;
      most = std::max(most, units), least = std::min(least, units);
    }
    INFO(plan.direct << " + " << plan.gather << " shares, " << pieces << " pieces, " << blocks << " blocks");
    CHECK(std::count(strip.begin(), strip.end(), 1) == int(strips));
    CHECK(std::count(block.begin(), block.end(), 1) == int(blocks));
    CHECK(shares.size() == std::min(plan.direct, strips) + std::min(plan.gather, blocks));
    if (strips) CHECK(most - least <= 1);
  }
}

// A lamp (E 1, black) at z = 0 facing +z over [0.4, 0.6]^2, cut into 16 x 16 squares: 256
// pieces. A receiver (rho 0.5) at z = 1 faces it; a black occluder at z = 0.5 covers x < 0.5. A
// penumbra pixel tests 64 segments to each of ~128 pieces the occluder may block, ~250,000 loop
// turns; one piece needs ~2,000.
TEST_CASE(
    "A lamp of 256 pieces behind an occluder, past llvmpipe's loop limit in one draw, is drawn in shares of its "
    "pieces: umbra black, lit pixels rho E times the whole lamp's exact form factor",
    "[gl][direct]") {
  test::backend();
  Scene scene;
  const int lamp = test::material(scene, 0.0, 1.0), grey = test::material(scene, 0.5, 0.0),
            black = test::material(scene, 0.0, 0.0);
  const int lampObject = scene.addObject("lamp");
  const int tiles = 16;
  for (int j = 0; j < tiles; ++j)
    for (int i = 0; i < tiles; ++i) {
      const double x0 = 0.4 + 0.2 * i / tiles, x1 = 0.4 + 0.2 * (i + 1) / tiles;
      const double y0 = 0.4 + 0.2 * j / tiles, y1 = 0.4 + 0.2 * (j + 1) / tiles;
      REQUIRE(scene.addPolygon({{x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0}, {x0, y1, 0}}, lamp, lampObject));
    }
  REQUIRE(scene.addPolygon({{-0.5, -0.5, 1}, {-0.5, 1.5, 1}, {1.5, 1.5, 1}, {1.5, -0.5, 1}}, grey,
                           scene.addObject("receiver")));
  REQUIRE(scene.addPolygon({{-1, -1, 0.5}, {0.5, -1, 0.5}, {0.5, 2, 0.5}, {-1, 2, 0.5}}, black,
                           scene.addObject("occluder")));
  const Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, 100));
  SolverState state(scene, atlas);
  const DirectLight light(scene, state.farDistance);
  REQUIRE(light.pieces() == tiles * tiles);
  Renderer renderer(state);
  renderer.show(std::vector<glm::vec4>(atlas.polygonOf.size(), glm::vec4(0.0f)));  // nothing reflects twice
  renderer.usePerPixelDirect(light);
  const int size = 32;
  const Camera camera{{0.5, 0.5, 0.6}, {0.5, 0.5, 1.0}, {0, 1, 0}, 90.0};  // between occluder and receiver
  const Image image = renderer.render(camera, size, size, 1);
  CHECK((renderer.lastShares().direct > 1) == gl::softwareRenderer());

  const Bvh bvh(scene);
  const Camera::PixelRays rays = camera.pixelRays(size, size);
  const cpu::Polygon whole{{0.4, 0.4, 0}, {0.6, 0.4, 0}, {0.6, 0.6, 0}, {0.4, 0.6, 0}};
  int umbra = 0, lit = 0;
  double brightestUmbra = 0, worstLit = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 d = glm::normalize(rays.corner + (x + 0.5) * rays.dx + (size - 1 - y + 0.5) * rays.dy);
      const glm::dvec3 hit = camera.eye + double(bvh.intersect(glm::vec3(camera.eye), glm::vec3(d), kNoPolygon)->t) * d;
      const double value = image.rgb[3 * (std::size_t(y) * size + x) + 1];
      if (hit.x < 0.39) brightestUmbra = std::max(brightestUmbra, value), ++umbra;
      if (hit.x > 0.61) {
        const double exact = 0.5 * cpu::pointToPolygon(hit, {0, 0, -1}, whole, {0, 0, 1});
        worstLit = std::max(worstLit, std::abs(value - exact) / exact), ++lit;
      }
    }
  INFO(renderer.lastShares().direct << " shares; worst lit error " << worstLit);
  REQUIRE(umbra > 100);
  REQUIRE(lit > 100);
  CHECK(brightestUmbra == 0);
  CHECK(worstLit < 1e-4);
}
