// camera.frag's atlas lookup against its CPU twin Atlas::sample: a triangle (its hypotenuse cuts
// texels, so lookups there mask out texels of no element) beside a pentagon, random per-texel
// values, rendered through the Renderer on the GL backend, compared pixel by pixel.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>
#include <random>

#include "src/output/Renderer.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
// Signed distance of p (in the z = 0 plane) inside the convex counter-clockwise polygon: > 0 inside.
double insideBy(const Poly3& poly, const glm::dvec3& p) {
  double d = 1e30;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 a(poly[i]), b(poly[(i + 1) % poly.size()]), e = glm::normalize(b - a);
    d = std::min(d, e.x * (p.y - a.y) - e.y * (p.x - a.x));
  }
  return d;
}

// Whether the bilinear footprint of `coord` holds a texel that is not of `polygon`'s chart.
bool masked(const Atlas& atlas, int polygon, glm::dvec2 coord) {
  const glm::ivec2 i0(glm::floor(coord - 0.5));
  for (int k = 0; k < 4; ++k) {
    const glm::ivec2 t = i0 + glm::ivec2(k & 1, k >> 1);
    if (t.x < 0 || t.y < 0 || t.x >= atlas.width || t.y >= atlas.height) return true;  // charts touch the border
    if (atlas.chartAt(std::size_t(t.y) * atlas.width + t.x) != atlas.chartOf[std::size_t(polygon)]) return true;
  }
  return false;
}

// A fan of triangles over convex `p` (one chart at --chart-angle 0: its outline is p).
std::vector<Poly3> fan(const Poly3& p) {
  std::vector<Poly3> out;
  for (std::size_t k = 1; k + 1 < p.size(); ++k) out.push_back({p[0], p[k], p[k + 1]});
  return out;
}

// Atlas::sample at p, or nothing where it jumps within `step` (float rounding in the shader's
// interpolated coordinates could land on the other side); a slope moves it far less than 0.01.
std::optional<glm::vec3> stableSample(const Atlas& atlas, const std::vector<glm::vec4>& values, int polygon,
                                      const glm::dvec3& p, double step) {
  const glm::vec3 v = atlas.sample(values, polygon, atlas.atlasCoord(polygon, p));
  for (const glm::dvec3 d :
       {glm::dvec3(step, 0, 0), glm::dvec3(-step, 0, 0), glm::dvec3(0, step, 0), glm::dvec3(0, -step, 0)}) {
    const glm::vec3 w = atlas.sample(values, polygon, atlas.atlasCoord(polygon, p + d));
    if (glm::length(w - v) > 1e-2f) return std::nullopt;
  }
  return v;
}
}  // namespace

TEST_CASE("camera.frag's masked bilinear atlas lookup equals Atlas::sample pixel by pixel", "[gl][camera]") {
  test::backend();
  const std::vector<Poly3> shapes = {Poly3{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                     Poly3{{1.2, 0, 0}, {2.2, 0.1, 0}, {2.3, 0.7, 0}, {1.7, 1.0, 0}, {1.2, 0.6, 0}}};
  // Each shape a polygon, or a fan of triangles: one chart each either way, looked up across the cuts.
  const bool tessellated = GENERATE(false, true);
  Scene scene;
  const int m = test::material(scene, 0.5, 0.0), o = scene.addObject("shapes");
  for (const Poly3& s : shapes)
    for (const Poly3& piece : tessellated ? fan(s) : std::vector<Poly3>{s}) REQUIRE(scene.addPolygon(piece, m, o));
  const Atlas atlas = buildAtlas(scene, 0.2);  // texels of 14 x 14 pixels: wide masked bands along the edges
  REQUIRE(atlas.charts.size() == 2);
  // Elements get values in [0.2, 1]; texels of no element 100, so any that leaks in shows.
  std::mt19937 rng(27);
  std::uniform_real_distribution<float> u(0.2f, 1.0f);
  std::vector<glm::vec4> values(atlas.polygonOf.size());
  for (std::size_t t = 0; t < values.size(); ++t)
    values[t] = atlas.polygonOf[t] == kNoPolygon ? glm::vec4(100.0f) : glm::vec4(u(rng), u(rng), u(rng), 1.0f);
  SolverState state(scene, atlas);
  gl::Texture texture(GL_RGBA32F, atlas.width, atlas.height);
  texture.upload(GL_RGBA, GL_FLOAT, values.data());

  const int W = 176, H = 80;
  const Camera camera{{1.15, 0.5, 3.0}, {1.15, 0.5, 0.0}, {0, 1, 0}, 22.0};
  const Image image = Renderer(state).render(camera, W, H, 1, texture);
  const Camera::PixelRays rays = camera.pixelRays(W, H);
  const double pixel = 2 * 3.0 * std::tan(glm::radians(11.0)) / H;  // a pixel's side in the plane z = 0
  int compared = 0, maskedCompared = 0, background = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const glm::dvec3 dir = rays.corner + (x + 0.5) * rays.dx + (H - 1 - y + 0.5) * rays.dy;  // GL rows bottom-up
      const glm::dvec3 p = camera.eye - camera.eye.z / dir.z * dir;
      const glm::vec3 shown(image.rgb[(std::size_t(y) * W + x) * 3], image.rgb[(std::size_t(y) * W + x) * 3 + 1],
                            image.rgb[(std::size_t(y) * W + x) * 3 + 2]);
      INFO("pixel " << x << ", " << y << " at " << p.x << ", " << p.y);
      const double in0 = insideBy(shapes[0], p), in1 = insideBy(shapes[1], p);
      if (std::max(in0, in1) < -pixel) {  // clear of both: the background
        CHECK(shown == glm::vec3(0.0f));
        ++background;
        continue;
      }
      const int polygon = in0 > in1 ? 0 : 1;     // a polygon of the shape's chart (the triangle's fan is itself)
      if (std::max(in0, in1) < pixel) continue;  // at an edge: coverage is the rasteriser's call
      const std::optional<glm::vec3> expect = stableSample(atlas, values, polygon, p, 1e-3 * atlas.texelSize);
      if (!expect) continue;
      CHECK(glm::length(shown - *expect) < 1e-3f);  // float coordinates: ~1e-4 texel, values differ by ~0.3
      ++compared;
      maskedCompared += masked(atlas, polygon, atlas.atlasCoord(polygon, p));
    }
  CHECK(compared > 3000);
  CHECK(maskedCompared > 300);  // lookups along the hypotenuse and the pentagon's slanted edges
  CHECK(background > 1000);
}

TEST_CASE("A camera render read back with a pixel whose alpha is not 1 is an error, not an image", "[cpu][camera]") {
  std::vector<float> rgba(4 * 16, 1.0f);  // every pass keeps alpha 1
  CHECK_NOTHROW(requireDrawn(rgba));
  rgba[4 * 7 + 3] = 0.0f;  // pixel 7 was never drawn: zeros, as the H100 read back
  CHECK_THROWS_WITH(requireDrawn(rgba), Catch::Contains("pixel 7 with alpha 0"));
  CHECK_THROWS(requireDrawn(std::vector<float>(4 * 16, 0.0f)));
}
