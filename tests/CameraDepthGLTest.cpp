// Camera images resolve surfaces much closer together than the scene is large (reversed-Z float
// depth, near plane from the scene's bounds): a Cornell light hung 0.5 mm below a whole ceiling,
// seen from 5 m, must show its own emission in every pixel it covers.
#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "src/output/Renderer.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// The Cornell box with one whole ceiling and the light hung 0.5 mm below it (the shipped scene
// cuts the light out of the ceiling instead).
Scene hungLightCornell() {
  Scene cornell = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  Scene s;
  for (const Material& m : cornell.materials) s.addMaterial(m);
  bool ceilingDone = false;
  for (const ScenePolygon& p : cornell.polygons()) {
    const std::string& name = cornell.objects[size_t(p.object)].name;
    const int object = s.addObject(name);
    Poly3 v = p.vertices;
    if (name == "ceiling") {  // drawn before the light, as in the OBJ: depth ties go to the ceiling
      if (!ceilingDone)
        s.addPolygon({{0, 548.8, 0}, {556, 548.8, 0}, {556, 548.8, 559.2}, {0, 548.8, 559.2}}, p.material, object);
      ceilingDone = true;
      continue;
    }
    if (name == "light")
      for (glm::dvec3& q : v) q.y -= 0.5;
    s.addPolygon(v, p.material, object);
  }
  return s;
}

// Pixel (column, row from the top) of point p in a width x height image of `vp`.
glm::dvec2 pixelOf(const glm::mat4& vp, const glm::dvec3& p, int width, int height) {
  glm::dvec4 c = glm::dmat4(vp) * glm::dvec4(p, 1.0);
  return {(c.x / c.w * 0.5 + 0.5) * width, (0.5 - c.y / c.w * 0.5) * height};
}

// Distance from q to the outside of the convex polygon `corners` (negative: outside).
double insideBy(const std::vector<glm::dvec2>& corners, glm::dvec2 q) {
  double least = 1e300, sign = 0;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    glm::dvec2 a = corners[i], b = corners[(i + 1) % corners.size()], e = b - a;
    double d = (e.x * (q.y - a.y) - e.y * (q.x - a.x)) / glm::length(e);
    if (sign == 0) sign = d < 0 ? -1 : 1;
    least = std::min(least, d * sign);
  }
  return least;
}

}  // namespace

TEST_CASE("A light hung 0.5 mm below the ceiling carries its emission in every pixel it covers, seen from 5 m",
          "[heavy][gl][camera]") {
  test::backend();
  Scene scene = hungLightCornell();
  Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, 2000));
  SolverState state(scene, atlas);  // before any shot: B = E, so the light shows E and the ceiling 0
  Renderer renderer(state);
  renderer.setAmbient(false);
  const Camera camera{{278, 273, -5000}, {278, 273, 0}, {0, 1, 0}, 8.0};
  const int w = 1024, h = 1024;
  Image img = renderer.render(camera, w, h, 1);

  int light = -1;
  for (std::size_t p = 0; p < scene.polygons().size(); ++p)
    if (scene.materials[scene.polygons()[p].material].emissive()) light = int(p);
  REQUIRE(light >= 0);
  const glm::dvec3 E = scene.materials[scene.polygons()[size_t(light)].material].emission;
  CameraMesh mesh(scene, atlas);
  const glm::mat4 vp = mesh.viewProjection(camera, double(w) / h);
  std::vector<glm::dvec2> corners;
  for (const glm::dvec3& v : scene.polygons()[size_t(light)].vertices) corners.push_back(pixelOf(vp, v, w, h));

  // Pixel centres at least 1.5 pixels inside the light's outline see only the light.
  int covered = 0, showingE = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (insideBy(corners, {x + 0.5, y + 0.5}) < 1.5) continue;
      ++covered;
      const float* px = &img.rgb[(std::size_t(y) * w + x) * 3];
      showingE += std::abs(px[0] - E.x) < 1e-4 * E.x && std::abs(px[1] - E.y) < 1e-4 * E.y &&
                  std::abs(px[2] - E.z) < 1e-4 * E.z;
    }
  INFO("covered " << covered << ", showing E " << showingE);
  CHECK(covered > 300);  // a strip ~180 x 7 pixels
  CHECK(showingE == covered);
}
