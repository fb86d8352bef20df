#include "src/viewer/ViewerWindow.h"

#include <GLFW/glfw3.h>  // with <GL/gl.h>, for its types and enums only: calls go through Gl below

#include <stdexcept>
#include <type_traits>
#include <utility>

namespace hemirad {

namespace {

std::string lastGlfwError;
void onGlfwError(int, const char* description) { lastGlfwError = description; }

[[noreturn]] void cannotOpen() {
  throw std::runtime_error("hemirad view: cannot open a window: " +
                           (lastGlfwError.empty() ? std::string("unknown GLFW error") : lastGlfwError) +
                           "; is DISPLAY set? (run under xvfb-run for headless use)");
}

}  // namespace

struct ViewerWindow::State {
  // The window context's own GL entry points (glfwGetProcAddress), for this thread only.
  struct Gl {
    void(APIENTRY* viewport)(GLint, GLint, GLsizei, GLsizei);
    void(APIENTRY* clearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
    void(APIENTRY* clear)(GLbitfield);
    void(APIENTRY* disable)(GLenum);
    void(APIENTRY* windowPos2i)(GLint, GLint);  // GL 1.4
    void(APIENTRY* pixelStorei)(GLenum, GLint);
    void(APIENTRY* drawPixels)(GLsizei, GLsizei, GLenum, GLenum, const void*);
    void(APIENTRY* readBuffer)(GLenum);
    void(APIENTRY* readPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*);

    void load() {
      auto get = [](auto& fn, const char* name) {
        fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(glfwGetProcAddress(name));
        if (!fn) throw std::runtime_error(std::string("hemirad view: the window's GL has no ") + name);
      };
      get(viewport, "glViewport");
      get(clearColor, "glClearColor");
      get(clear, "glClear");
      get(disable, "glDisable");
      get(windowPos2i, "glWindowPos2i");
      get(pixelStorei, "glPixelStorei");
      get(drawPixels, "glDrawPixels");
      get(readBuffer, "glReadBuffer");
      get(readPixels, "glReadPixels");
    }
  };

  GLFWwindow* window = nullptr;
  Gl gl{};
  Input input;
  bool dragging = false, damaged = true;
  glm::dvec2 cursor{0.0};
};

ViewerWindow::ViewerWindow(int width, int height, const std::string& title) : state_(std::make_unique<State>()) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) cannotOpen();
  state_->window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!state_->window) {
    glfwTerminate();
    cannotOpen();
  }
  GLFWwindow* w = state_->window;
  glfwSetWindowUserPointer(w, state_.get());
  glfwMakeContextCurrent(w);
  glfwSwapInterval(1);
  try {
    state_->gl.load();
  } catch (...) {
    glfwDestroyWindow(w);
    glfwTerminate();
    throw;
  }
  // 8-bit frames onto an 8-bit window: no dithering, so what is read back is what was drawn.
  state_->gl.disable(GL_DITHER);
  state_->gl.pixelStorei(GL_UNPACK_ALIGNMENT, 1);
  state_->gl.pixelStorei(GL_PACK_ALIGNMENT, 1);

  glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    static const std::pair<int, Action> keys[] = {{GLFW_KEY_1, Action::Progressive}, {GLFW_KEY_2, Action::Importance},
                                                  {GLFW_KEY_3, Action::Perspective}, {GLFW_KEY_R, Action::Restart},
                                                  {GLFW_KEY_M, Action::Ambient},     {GLFW_KEY_SPACE, Action::Pause},
                                                  {GLFW_KEY_P, Action::Screenshot},  {GLFW_KEY_ESCAPE, Action::Quit}};
    for (auto [k, a] : keys)
      if (k == key) static_cast<State*>(glfwGetWindowUserPointer(win))->input.actions.push_back(a);
  });
  glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
    if (button == GLFW_MOUSE_BUTTON_LEFT)
      static_cast<State*>(glfwGetWindowUserPointer(win))->dragging = action == GLFW_PRESS;
  });
  glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
    State* s = static_cast<State*>(glfwGetWindowUserPointer(win));
    if (s->dragging) s->input.drag += glm::dvec2(x, y) - s->cursor;
    s->cursor = {x, y};
  });
  glfwSetWindowRefreshCallback(
      w, [](GLFWwindow* win) { static_cast<State*>(glfwGetWindowUserPointer(win))->damaged = true; });
  glfwSetFramebufferSizeCallback(
      w, [](GLFWwindow* win, int, int) { static_cast<State*>(glfwGetWindowUserPointer(win))->damaged = true; });
}

ViewerWindow::~ViewerWindow() {
  glfwDestroyWindow(state_->window);
  glfwTerminate();
}

bool ViewerWindow::closing() const { return glfwWindowShouldClose(state_->window); }
void ViewerWindow::wait(double seconds) { glfwWaitEventsTimeout(seconds); }
void ViewerWindow::wake() { glfwPostEmptyEvent(); }
void ViewerWindow::setTitle(const std::string& title) { glfwSetWindowTitle(state_->window, title.c_str()); }

glm::ivec2 ViewerWindow::framebufferSize() const {
  glm::ivec2 size;
  glfwGetFramebufferSize(state_->window, &size.x, &size.y);
  return size;
}

ViewerWindow::Input ViewerWindow::input() {
  GLFWwindow* w = state_->window;
  auto held = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0 : 0.0; };
  Input in = std::move(state_->input);
  state_->input = {};
  in.move = {held(GLFW_KEY_W) - held(GLFW_KEY_S), held(GLFW_KEY_D) - held(GLFW_KEY_A),
             held(GLFW_KEY_E) - held(GLFW_KEY_Q)};
  in.fast = held(GLFW_KEY_LEFT_SHIFT) + held(GLFW_KEY_RIGHT_SHIFT) > 0;
  return in;
}

bool ViewerWindow::damaged() { return std::exchange(state_->damaged, false); }

void ViewerWindow::draw(const ViewerFrame& frame) {
  const State::Gl& gl = state_->gl;
  const glm::ivec2 size = framebufferSize();
  gl.viewport(0, 0, size.x, size.y);
  gl.clearColor(0, 0, 0, 1);
  gl.clear(GL_COLOR_BUFFER_BIT);
  // A frame made before a resize keeps its top-left corner where it was.
  gl.windowPos2i(0, size.y - frame.height);
  gl.drawPixels(frame.width, frame.height, GL_RGBA, GL_UNSIGNED_BYTE, frame.rgba.data());
}

std::vector<std::uint8_t> ViewerWindow::readBack() const {
  const glm::ivec2 size = framebufferSize();
  std::vector<std::uint8_t> rgba(std::size_t(size.x) * size.y * 4);
  state_->gl.readBuffer(GL_BACK);
  state_->gl.readPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return rgba;
}

void ViewerWindow::swap() { glfwSwapBuffers(state_->window); }

}  // namespace hemirad
