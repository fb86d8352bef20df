#include "gl/Debug.h"

#include <fmt/format.h>

#include <cstdio>

#include "gl/Backend.h"
#include "gl/GL.h"

namespace hemirad::gl {

namespace {
void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                               const void*) {
  if (type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH)
    std::fprintf(stderr, "hemirad: GL debug: %s\n", message);
}
}  // namespace

void enableDebugOutput() {
  if (!glDebugMessageCallback) return;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
}

void checkErrors(std::string_view where) {
  GLenum e = glGetError();
  if (e != GL_NO_ERROR) throw Error(fmt::format("GL error 0x{:04x} in {}", e, where));
}

}  // namespace hemirad::gl
