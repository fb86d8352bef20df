#include "src/viewer/ViewerWorker.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <utility>

#include "src/base/Clock.h"
#include "src/output/Image.h"
#include "src/output/InstantRenderer.h"
#include "src/output/Renderer.h"
#include "src/scene/Atlas.h"

namespace hemirad {

namespace {

bool sameView(const ViewerControls& a, const ViewerControls& b) {
  return a.camera == b.camera && a.width == b.width && a.height == b.height;
}

// toneMap's RGB rows top-down to RGBA rows bottom-up, as glDrawPixels takes them.
std::vector<std::uint8_t> bottomUpRgba(const std::vector<unsigned char>& rgb, int width, int height) {
  std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4, 255);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        rgba[(std::size_t(height - 1 - y) * width + x) * 4 + c] = rgb[(std::size_t(y) * width + x) * 3 + c];
  return rgba;
}

// One frame's shots, from a solve's `solveFrames`-th frame that started at t0.
SolveStatus shootFrame(const ViewerOptions& o, ProgressiveSolver& solver, SolveStatus status, unsigned& batch,
                       unsigned solveFrames, Clock::time_point t0) {
  if (o.shotsPerFrame) {
    // Whole passes until k x N shots at this solve's k-th frame: a pass shoots up to
    // --shooters-per-pass blocks, fewer while few have unshot power, so passes cannot be counted.
    const std::uint64_t target = std::uint64_t(solveFrames + 1) * o.shotsPerFrame;
    while (!status.done && status.shots < target)
      status = solver.advance(unsigned(std::min<std::uint64_t>(target - status.shots, o.shotsPerFrame)));
    return status;
  }
  bool first = true;  // batches until the frame's budget is spent, at least one a frame
  return advanceWhile(solver, status, batch, [&] { return std::exchange(first, false) || msSince(t0) < o.frameMs; });
}

// Hands the frame to the window once it took the last one; false when the viewer stops.
bool publish(ViewerLink& link, ViewerFrame&& frame) {
  {
    std::unique_lock lock(link.mutex);
    link.changed.wait(lock, [&] { return link.stop || !link.frame; });
    if (link.stop) return false;
    link.frame = std::move(frame);
  }
  link.wake();
  return true;
}

// Instant radiosity: the VPLs and their shadow maps once, then each frame is a camera move
// (G-buffer and shading only). With --frame-count every frame is made; else only on a change.
void workInstant(const ViewerOptions& o, const Scene& scene, ViewerLink& link) {
  auto backend = gl::createBackend(o.backend);
  if (o.backend.kind == gl::BackendKind::Auto)
    fmt::print(stderr, "hemirad: backend auto chose {} ({})\n", backend->name(), backend->renderer());
  VplTracer tracer(scene, o.instant);
  tracer.trace();
  InstantRenderer renderer(scene, tracer, o.instant);  // after the backend: destroyed while it is current
  ViewerControls shown;
  unsigned frames = 0;
  for (;;) {
    ViewerControls c;
    {
      std::unique_lock lock(link.mutex);
      link.changed.wait(lock, [&] {
        const bool idle = frames && (o.frames ? frames >= o.frames : link.controls.version == shown.version);
        return link.stop || !idle;
      });
      if (link.stop) return;
      c = link.controls;
    }
    const auto t0 = Clock::now();
    const Image image = renderer.render(c.camera, c.width, c.height, 1, o.shading).image;
    ViewerFrame frame{
        c.width,   c.height,      bottomUpRgba(toneMap(image, exposureScale(image, o.exposure)), c.width, c.height),
        "instant", SolveStatus{}, msSince(t0)};
    shown = c;
    ++frames;
    if (!publish(link, std::move(frame))) return;
  }
}

void workProgressive(const ViewerOptions& o, const Scene& scene, ViewerLink& link) {
  auto backend = gl::createBackend(o.backend);
  if (o.backend.kind == gl::BackendKind::Auto)
    fmt::print(stderr, "hemirad: backend auto chose {} ({})\n", backend->name(), backend->renderer());
  const Atlas atlas = buildAtlas(scene, o.discretisation, backend->maxTextureSize());
  // Declared after the backend: destroyed while its context is still current.
  std::unique_ptr<SolverState> state;
  std::unique_ptr<ProgressiveSolver> solver;
  std::unique_ptr<Renderer> renderer;
  ProgressiveSettings settings = o.progressive;
  ViewerControls shown;  // the controls the last frame was made with
  SolveStatus status;
  unsigned batch = 1, frames = 0, solveFrames = 0;  // frames made, and since the last (re)start

  // Nothing to shoot and nothing changed: no frame to make. With --frames every frame is made,
  // changed or not, so the count is exact.
  auto idle = [&](const ViewerControls& c) {
    if (!solver) return false;
    if (o.frames) return frames >= o.frames;
    return (status.done || c.paused) && c.version == shown.version;
  };
  for (;;) {
    ViewerControls c;
    {
      std::unique_lock lock(link.mutex);
      link.changed.wait(lock, [&] { return link.stop || !idle(link.controls); });
      if (link.stop) return;
      c = link.controls;
    }
    const auto t0 = Clock::now();
    const bool fresh = !solver || c.algorithm != shown.algorithm || c.restarts != shown.restarts;
    if (fresh) {  // a new solve from B = E
      renderer.reset();
      solver.reset();
      state.reset();
      state = std::make_unique<SolverState>(scene, atlas);
      settings.algorithm = c.algorithm;
      solver = std::make_unique<ProgressiveSolver>(*state, settings);
      renderer = std::make_unique<Renderer>(*state);
      renderer->stitchLive();
      status = {};
      batch = 1;
      solveFrames = 0;
    }
    if (settings.importanceDriven() && (fresh || !sameView(c, shown))) {
      solver->look(c.camera, double(c.width) / c.height);
      status = solver->advance(0);  // a perspective-driven solve has entries to deliver again
    }
    if (!c.paused && !status.done) status = shootFrame(o, *solver, status, batch, solveFrames, t0);
    renderer->setAmbient(c.ambient);
    Image image = renderer->render(c.camera, c.width, c.height, 1);
    ViewerFrame frame{c.width,
                      c.height,
                      bottomUpRgba(toneMap(image, exposureScale(image, o.exposure)), c.width, c.height),
                      solver->algorithm(),
                      status,
                      msSince(t0)};
    shown = c;
    ++frames, ++solveFrames;
    if (!publish(link, std::move(frame))) return;
  }
}

using Work = void (*)(const ViewerOptions&, const Scene&, ViewerLink&);

// What the viewer shows for each method it runs, by --method name.
const std::map<std::string, Work>& works() {
  static const std::map<std::string, Work> table{{"instant", workInstant}, {"progressive", workProgressive}};
  return table;
}

}  // namespace

void runViewerWorker(const ViewerOptions& options, const Scene& scene, ViewerLink& link) {
  try {
    works().at(options.method)(options, scene, link);
  } catch (...) {
    {
      std::lock_guard lock(link.mutex);
      link.error = std::current_exception();
    }
    link.wake();
  }
}

std::vector<std::string> viewerMethods() {
  std::vector<std::string> names;
  for (const auto& [name, work] : works()) names.push_back(name);
  return names;
}

}  // namespace hemirad
