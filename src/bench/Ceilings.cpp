#include "src/bench/Ceilings.h"

#include <algorithm>
#include <chrono>
#include <functional>

#include "gl/Objects.h"
#include "gl/State.h"
#include "src/scene/ItemMesh.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/Control.h"
#include "src/solver/ItemBuffer.h"
#include "src/solver/ShaderContract.h"

namespace hemirad {

namespace {

// Seconds of the fastest of 5 timed runs of `work` (one untimed run first warms caches and
// shader compilation).
double bestSeconds(gl::RenderBackend& backend, const std::function<void()>& work) {
  double best = 1e300;
  for (int r = 0; r <= 5; ++r) {
    backend.finish();
    auto t0 = std::chrono::steady_clock::now();
    work();
    backend.finish();
    if (r > 0) best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int ceilingLevel(std::size_t sceneTriangles) {
  int level = 6;
  while (level > 0 && (sceneTriangles << (2 * level)) > kCeilingTriangles) --level;
  return level;
}

Ceilings measureCeilings(gl::RenderBackend& backend, const std::string& scenePath) {
  Ceilings c;
  // Compute: one RGBA32F texel loaded and stored per invocation over 4096^2, 10 times.
  const int side = 4096;
  {
    gl::Texture values(GL_RGBA32F, side, side);
    gl::Program kernel = computeProgram("ceiling.comp");
    kernel.use();
    values.bindImage(slot::IMAGE_CEILING_VALUES, GL_READ_WRITE);
    c.invocationsPerSecond = 10.0 * side * side / bestSeconds(backend, [&] {
                               for (int k = 0; k < 10; ++k) {
                                 gl::Program::dispatch(side / 16, side / 16);
                                 gl::barrier(gl::Barrier::Image);
                               }
                             });
  }
  // Fill: 8 full-target triangles, each nearer than the last, into a 2048^2 id + depth target.
  {
    const int fillSide = 2048, layers = 8;
    gl::Texture id(GL_R32UI, fillSide, fillSide, 1), depth(GL_DEPTH_COMPONENT32F, fillSide, fillSide, 1);
    gl::Framebuffer target;
    target.attach(GL_COLOR_ATTACHMENT0, id);
    target.attach(GL_DEPTH_ATTACHMENT, depth);
    target.checkComplete("fill ceiling");
    gl::Program fill = renderProgram("fill.vert", "fill.frag");
    fill.set("instances", layers);
    gl::VertexArray empty;
    c.fragmentsPerSecond = double(layers) * fillSide * fillSide / bestSeconds(backend, [&] {
                             target.clearDepth(1.0f);
                             target.bind();
                             gl::RasterState{.width = fillSide, .height = fillSide}.apply();
                             fill.use();
                             empty.bind();
                             gl::drawTriangles(3, layers);
                           });
  }
  // Triangles: the item mesh at L6 (or lower, see ceilingLevel) from the scene's top, 10 times.
  Scene scene = loadScene(scenePath);
  c.triangleLevel = ceilingLevel(itemTriangleCount(scene, 0));
  ItemBuffer items(scene, c.triangleLevel, 512, 2.0 * glm::length(scene.boundsMax() - scene.boundsMin()));
  ControlBlock control{};
  control.count = 1;
  glm::dvec3 lo = scene.boundsMin(), hi = scene.boundsMax();
  ShooterRecord& shooter = control.shooter[0];
  shooter.positionArea[0] = float(0.5 * (lo.x + hi.x));  // the ceiling's centre, facing down
  shooter.positionArea[1] = float(hi.y - 1e-3 * (hi.y - lo.y));
  shooter.positionArea[2] = float(0.5 * (lo.z + hi.z));
  shooter.normal[1] = -1.0f;
  gl::Buffer controlBuffer(sizeof control, &control);
  c.trianglesPerSecond = 10.0 * double(items.triangles()) / bestSeconds(backend, [&] {
                           for (int k = 0; k < 10; ++k) items.render(controlBuffer);
                         });
  return c;
}

}  // namespace hemirad
