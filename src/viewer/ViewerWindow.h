// The viewer's window (GLFW, a compatibility GL context of its own): input, and presenting the
// worker's frames with glDrawPixels. Only the window thread touches it. It resolves the few GL
// 1.x functions it needs itself, never through glad, whose pointers belong to the worker's
// backend context.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <memory>
#include <string>
#include <vector>

#include "src/viewer/ViewerLink.h"

namespace hemirad {

class ViewerWindow {
 public:
  enum class Action { Progressive, Importance, Perspective, Restart, Ambient, Pause, Screenshot, Quit };
  struct Input {
    glm::dvec2 drag{0.0};         // screen units the mouse moved with the left button held
    glm::dvec3 move{0.0};         // held keys: forward (W/S), right (D/A), up (E/Q), each -1..1
    bool fast = false;            // shift held
    std::vector<Action> actions;  // keys pressed since the last input(), in order
  };

  // Throws std::runtime_error, one line, if there is no display or no window.
  ViewerWindow(int width, int height, const std::string& title);
  ~ViewerWindow();
  ViewerWindow(const ViewerWindow&) = delete;
  ViewerWindow& operator=(const ViewerWindow&) = delete;

  bool closing() const;
  // Handles events, waiting for one at most `seconds`.
  void wait(double seconds);
  static void wake();  // from any thread: ends a wait()
  glm::ivec2 framebufferSize() const;
  void setTitle(const std::string& title);
  Input input();
  bool damaged();  // exposed or resized since the last call: draw again

  void draw(const ViewerFrame& frame);         // into the back buffer, top-left aligned
  std::vector<std::uint8_t> readBack() const;  // the back buffer, RGBA rows bottom-up
  void swap();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace hemirad
