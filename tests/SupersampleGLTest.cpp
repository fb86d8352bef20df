// --supersample N beyond one framebuffer (src/output/Supersample.h): shifted draws at 8 x (or
// N's largest divisor up to 8) must sample each pixel on exactly the regular N x N grid, whose box
// filter tends to the pixel's integral (what the path-traced reference estimates) as N grows.
#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "src/output/Renderer.h"
#include "src/output/Supersample.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
const Poly3 kTriangle{{0, 0, 0}, {1, 0.137, 0}, {0.31, 0.93, 0}};

// Signed distance of p (z = 0) inside the counter-clockwise triangle: > 0 inside.
double insideBy(const glm::dvec3& p) {
  double d = 1e30;
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::dvec2 a(kTriangle[i]), e = glm::normalize(glm::dvec2(kTriangle[(i + 1) % 3]) - a);
    d = std::min(d, e.x * (p.y - a.y) - e.y * (p.x - a.x));
  }
  return d;
}

struct Coverage {
  double grid = 0;         // the share of the N x N grid's sample centres inside
  bool ambiguous = false;  // a sample within float rounding of an edge: the rasteriser's call
};

// Pixel (x, y) (image rows top-down) of a W x H view: its N x N sample centres traced to z = 0.
Coverage gridCoverage(const Camera& camera, int W, int H, int x, int y, int n) {
  const Camera::PixelRays rays = camera.pixelRays(W, H);
  Coverage c;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec3 dir = rays.corner + (x + (i + 0.5) / n) * rays.dx + (H - 1 - y + (j + 0.5) / n) * rays.dy;
      const double in = insideBy(camera.eye - camera.eye.z / dir.z * dir);
      c.ambiguous = c.ambiguous || std::abs(in) < 1e-5;
      c.grid += in > 0 ? 1.0 / (n * n) : 0.0;
    }
  return c;
}
}  // namespace

TEST_CASE("Supersample grids split N into a framebuffer factor of at most 8 and shifted draws", "[camera]") {
  for (auto [n, scale, draws] :
       {std::tuple{1, 1, 1}, {7, 7, 1}, {8, 8, 1}, {12, 6, 4}, {16, 8, 4}, {32, 8, 16}, {64, 8, 64}, {11, 1, 121}}) {
    const SupersampleGrid grid(n);
    CHECK(grid.scale() == scale);
    CHECK(grid.draws() == draws);
  }
}

TEST_CASE("Supersampled camera pixels average exactly the regular N x N grid, nearing their coverage as N grows",
          "[gl][camera][heavy]") {
  test::backend();
  Scene scene;
  REQUIRE(scene.addPolygon(kTriangle, test::material(scene, 0.5, 0.0), scene.addObject("triangle")));
  const Atlas atlas = buildAtlas(scene, 0.05);
  SolverState state(scene, atlas);
  gl::Texture ones(GL_RGBA32F, atlas.width, atlas.height);  // B = 1 on the triangle: a pixel shows its coverage
  ones.upload(GL_RGBA, GL_FLOAT, std::vector<glm::vec4>(atlas.polygonOf.size(), glm::vec4(1.0f)).data());
  const int W = 24, H = 24;
  const Camera camera{{0.45, 0.45, 3.0}, {0.45, 0.45, 0.0}, {0, 1, 0}, 21.0};
  Renderer renderer(state);
  std::map<int, double> errors;
  for (int n : {4, 8, 12, 16, 32}) {  // 12, 16 and 32: framebuffers of 6 x and 8 x, drawn 4, 4 and 16 times
    const Image image = renderer.render(camera, W, H, n, ones);
    int edgePixels = 0;
    double error = 0;  // mean |grid share - 256 x 256's share| over pixels the edges cross
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const Coverage c = gridCoverage(camera, W, H, x, y, n);
        if (c.ambiguous) continue;
        INFO("N " << n << ", pixel " << x << ", " << y);
        CHECK(std::abs(image.rgb[(std::size_t(y) * W + x) * 3] - c.grid) < 1e-5);
        const double fine = gridCoverage(camera, W, H, x, y, 256).grid;  // stands in for the integral
        if (fine == 0 || fine == 1) continue;
        error += std::abs(c.grid - fine);
        ++edgePixels;
      }
    REQUIRE(edgePixels > 40);
    error /= edgePixels;
    errors[n] = error;
  }
  INFO("mean |coverage error| over the edge pixels at N 4, 8, 12, 16, 32: "
       << errors[4] << ", " << errors[8] << ", " << errors[12] << ", " << errors[16] << ", " << errors[32]);
  // A regular grid's error on an edge falls as 1 / N, not monotonically (aliasing): 4 -> 32 by 4 at least.
  CHECK(errors[32] < errors[4] / 4);
  CHECK(errors[32] < errors[8] / 2);
}
