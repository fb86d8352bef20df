// What the viewer's two threads share: the window thread writes the controls (camera, algorithm,
// switches), the worker thread (GL backend, solver, renderer) answers with frames. One frame
// slot: the worker waits for the window to take a frame before it hands over the next, so
// every frame is presented and none is rendered for nothing. No GL types here: the window
// side must not see glad.
#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "src/scene/Camera.h"
#include "src/solver/Solver.h"

namespace hemirad {

struct ViewerControls {
  Camera camera;
  int width = 1, height = 1;  // the window's framebuffer, in pixels
  Algorithm algorithm = Algorithm::Progressive;
  bool ambient = true, paused = false;
  unsigned restarts = 0;  // bumped by R: a fresh solve
  unsigned version = 0;   // bumped by every change, so the worker sees one
};

struct ViewerFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgba;  // tone-mapped, rows bottom-up (glDrawPixels order)
  std::string algorithm;
  SolveStatus status;
  double ms = 0;  // shooting and rendering it took
};

struct ViewerLink {
  std::mutex mutex;
  std::condition_variable changed;  // controls, frame taken, stop
  ViewerControls controls;
  std::optional<ViewerFrame> frame;  // handed over, not yet taken
  std::exception_ptr error;          // the worker's, rethrown on the window thread
  bool stop = false;
  std::function<void()> wake;  // wakes the window thread (glfwPostEmptyEvent); thread-safe

  // Window side: the frame waiting, if any; frees the slot for the next.
  std::optional<ViewerFrame> take() {
    std::optional<ViewerFrame> f;
    {
      std::lock_guard lock(mutex);
      f.swap(frame);
    }
    changed.notify_all();
    return f;
  }
  void update(const ViewerControls& c) {
    {
      std::lock_guard lock(mutex);
      controls = c;
    }
    changed.notify_all();
  }
};

}  // namespace hemirad
