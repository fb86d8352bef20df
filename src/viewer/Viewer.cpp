#include "src/viewer/Viewer.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <optional>
#include <thread>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/ImageFile.h"
#include "src/solver/Control.h"
#include "src/viewer/ViewerWindow.h"
#include "src/viewer/ViewerWorker.h"

namespace hemirad {

namespace {

constexpr const char* kControls =
    "  left-drag  look around            W/S A/D Q/E  move forward/back, left/right, down/up (shift: faster)\n"
    "  1 2 3      restart as progressive / importance / perspective\n"
    "  R          restart the solve      M            ambient term on/off\n"
    "  Space      pause shooting         P            screenshot now (--screenshot, or hemirad-view.png)\n"
    "  Esc        quit\n";

// Turns the view about the eye: yaw about the up axis, pitch towards it, stopping short of it.
Camera turned(Camera c, double yaw, double pitch) {
  const glm::dvec3 up = glm::normalize(c.up), d = c.target - c.eye;
  const double distance = glm::length(d);
  const glm::dvec3 dir = d / distance;
  glm::dvec3 flat = dir - up * glm::dot(dir, up);
  if (glm::length(flat) < 1e-9) flat = glm::cross(up, std::abs(up.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
  const glm::dvec3 forward = glm::normalize(flat), right = glm::cross(forward, up);
  const double limit = glm::radians(89.0);
  const double elevation = std::clamp(std::asin(std::clamp(glm::dot(dir, up), -1.0, 1.0)) + pitch, -limit, limit);
  const glm::dvec3 horizontal = std::cos(yaw) * forward + std::sin(yaw) * right;
  c.target = c.eye + distance * (std::cos(elevation) * horizontal + std::sin(elevation) * up);
  return c;
}

// Moves eye and target together by `step` along the view's forward, right and up axes.
Camera moved(Camera c, const glm::dvec3& axes, double step) {
  const glm::dvec3 forward = glm::normalize(c.target - c.eye), up = glm::normalize(c.up);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
  const glm::dvec3 delta = step * (axes.x * forward + axes.y * right + axes.z * up);
  c.eye += delta;
  c.target += delta;
  return c;
}

void writeScreenshot(const std::string& path, glm::ivec2 size, const std::vector<std::uint8_t>& rgba) {
  std::vector<std::uint8_t> rgb(std::size_t(size.x) * size.y * 3);  // rows top-down
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      for (int c = 0; c < 3; ++c)
        rgb[(std::size_t(y) * size.x + x) * 3 + c] = rgba[(std::size_t(size.y - 1 - y) * size.x + x) * 4 + c];
  writeFileBytes(path, encodePng8(size.x, size.y, rgb));
}

// A key's change to the controls: 1/2/3 and R restart the solve.
void apply(ViewerControls& c, ViewerWindow::Action a) {
  using A = ViewerWindow::Action;
  switch (a) {
    case A::Progressive:
      c.algorithm = Algorithm::Progressive, ++c.restarts;
      break;
    case A::Importance:
      c.algorithm = Algorithm::Importance, ++c.restarts;
      break;
    case A::Perspective:
      c.algorithm = Algorithm::Perspective, ++c.restarts;
      break;
    case A::Restart:
      ++c.restarts;
      break;
    case A::Ambient:
      c.ambient = !c.ambient;
      break;
    case A::Pause:
      c.paused = !c.paused;
      break;
    case A::Screenshot:
    case A::Quit:
      break;  // not controls: the window loop's own
  }
}

std::string title(const ViewerFrame& f, double fps, bool paused) {
  if (f.algorithm == "instant") return fmt::format("hemirad — instant radiosity — {:.0f} fps", fps);
  return fmt::format("hemirad — {} — {} shots — convergence {:.4f} — {:.0f} fps{}", f.algorithm, f.status.shots,
                     f.status.convergence, fps, paused ? " — paused" : "");
}

// Stops the worker and waits for it, however the window loop ends (errors included).
struct WorkerThread {
  ViewerLink& link;
  std::thread thread;
  ~WorkerThread() {
    {
      std::lock_guard lock(link.mutex);
      link.stop = true;
    }
    link.changed.notify_all();
    thread.join();
  }
};

ViewerControls initialControls(const ViewerOptions& o, const Camera& start, glm::ivec2 size) {
  ViewerControls controls;
  controls.camera = start;
  controls.algorithm = o.progressive.algorithm;
  controls.ambient = o.ambient;
  controls.width = std::max(size.x, 1);
  controls.height = std::max(size.y, 1);
  controls.version = 1;
  return controls;
}

// The controls after a frame's input (moves of `step`, a resize, keys but quit and screenshot);
// `changed` when they differ.
ViewerControls steered(const ViewerControls& controls, const ViewerWindow::Input& in, glm::ivec2 size, double step,
                       bool& changed) {
  ViewerControls next = controls;
  if (in.drag != glm::dvec2(0.0)) next.camera = turned(next.camera, in.drag.x * 0.005, -in.drag.y * 0.005);
  if (in.move != glm::dvec3(0.0)) next.camera = moved(next.camera, in.move, step * (in.fast ? 4 : 1));
  if (size.x > 0 && size.y > 0) next.width = size.x, next.height = size.y;  // not while minimised
  changed = in.drag != glm::dvec2(0.0) || in.move != glm::dvec3(0.0) || next.width != controls.width ||
            next.height != controls.height;
  for (ViewerWindow::Action a : in.actions)
    if (a != ViewerWindow::Action::Quit && a != ViewerWindow::Action::Screenshot) apply(next, a), changed = true;
  return next;
}

// Frames presented per second, over half a second or more.
struct FrameRate {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  unsigned frames = 0;
  double fps = 0;
  void presented(std::chrono::steady_clock::time_point now) {
    ++frames;
    if (double s = std::chrono::duration<double>(now - start).count(); s >= 0.5)
      fps = frames / s, frames = 0, start = now;
  }
};

}  // namespace

const char* viewerControls() { return kControls; }

namespace {

// The window's loop: input becomes the worker's controls, the worker's frames are shown, until
// quit, the window closes, the worker fails or --frames frames were presented.
void interact(const ViewerOptions& o, ViewerWindow& window, ViewerLink& link, ViewerControls& controls,
              std::optional<ViewerFrame>& shown, unsigned& presented, double speed,
              const std::function<void(const std::string&)>& screenshot) {
  using Clock = std::chrono::steady_clock;
  auto last = Clock::now();
  FrameRate rate;
  bool quit = false;
  while (!quit && !window.closing()) {
    window.wait(1.0 / 60);
    const auto now = Clock::now();
    const double dt = std::min(std::chrono::duration<double>(now - last).count(), 0.1);
    last = now;

    ViewerWindow::Input in = window.input();
    bool changed = false;
    ViewerControls next = steered(controls, in, window.framebufferSize(), speed * dt, changed);
    for (ViewerWindow::Action a : in.actions) {
      if (a == ViewerWindow::Action::Quit) quit = true;
      if (a != ViewerWindow::Action::Screenshot) continue;
      const std::string path = o.screenshot.empty() ? "hemirad-view.png" : o.screenshot;
      try {  // a failure is worth a warning, not the session
        screenshot(path);
        fmt::print(stderr, "hemirad view: screenshot written: {}\n", path);
      } catch (const std::exception& e) {
        warn(e.what());
      }
      window.swap();
    }
    if (changed) {
      ++next.version;
      controls = next;
      link.update(controls);
    }
    {
      std::lock_guard lock(link.mutex);
      if (link.error) break;
    }
    if (std::optional<ViewerFrame> f = link.take()) {
      shown = std::move(f);
      window.draw(*shown);
      window.swap();
      ++presented;
      rate.presented(now);
      window.setTitle(title(*shown, rate.fps, controls.paused));
      if (o.frames && presented >= o.frames) break;
    } else if (window.damaged() && shown) {
      window.draw(*shown);
      window.swap();
    }
  }
}

}  // namespace

int runView(ViewerOptions o) {
  if (!o.screenshot.empty()) {
    checkExtension(o.screenshot, "--screenshot", {".png"}, false);
    checkWritable(o.screenshot, "--screenshot");
  }
  // Counted frames of counted shots: the solve stops at their product, so the last frame shows
  // what `solve --shots N x F` would (the same passes; only the last one can be cut short).
  if (o.shotsPerFrame && o.frames) {
    unsigned& max = o.progressive.stop.maxShots;
    max = unsigned(std::min<std::uint64_t>(max ? max : ~0u, std::uint64_t(o.shotsPerFrame) * o.frames));
  }
  // Bad input fails here, before any window, as it does for `solve`.
  Scene scene = loadScene(o.scene, o.load);
  printWarnings(scene.warnings);
  validateSolvable(scene);
  const Camera start = resolveCamera(scene, o.camera);
  const double speed = 0.3 * glm::length(scene.boundsMax() - scene.boundsMin());  // scene units per second

  ViewerWindow window(o.width, o.height, "hemirad");
  fmt::print(stderr, "hemirad view: controls:\n{}", kControls);
  ViewerLink link;
  link.wake = &ViewerWindow::wake;
  ViewerControls controls = initialControls(o, start, window.framebufferSize());
  link.controls = controls;

  std::optional<ViewerFrame> shown;
  unsigned presented = 0;
  auto screenshot = [&](const std::string& path) {
    if (!shown) return warn("no frame shown yet: no screenshot");
    window.draw(*shown);
    writeScreenshot(path, window.framebufferSize(), window.readBack());
  };
  {
    WorkerThread worker{link, std::thread(runViewerWorker, std::cref(o), std::cref(scene), std::ref(link))};
    interact(o, window, link, controls, shown, presented, speed, screenshot);
  }  // the worker has stopped
  if (link.error) std::rethrow_exception(link.error);
  if (!o.screenshot.empty()) screenshot(o.screenshot);
  if (o.method == "instant") {
    fmt::print(stderr, "hemirad view: instant, {} VPLs, {} shading, interleave {}, {} frames\n", o.instant.vpls,
               shadingName(o.shading), o.instant.interleave, presented);
    return 0;
  }
  fmt::print(stderr, "hemirad view: {}, {} shots, convergence {:.4f}, {} frames\n",
             shown ? shown->algorithm : algorithmName(controls.algorithm), shown ? shown->status.shots : 0,
             shown ? shown->status.convergence : 0.0, presented);
  return 0;
}

}  // namespace hemirad
