#include "gl/Debug.h"

#include <fmt/format.h>

#include <cstdio>
#include <utility>

#include "gl/Backend.h"
#include "gl/GL.h"

namespace hemirad::gl {

namespace {
std::string firstError;  // the first KHR_debug API error since the last takeDebugError()

const char* typeName(GLenum type) {
  switch (type) {
    case GL_DEBUG_TYPE_ERROR:
      return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
      return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
      return "undefined behaviour";
    case GL_DEBUG_TYPE_PORTABILITY:
      return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
      return "performance";
    case GL_DEBUG_TYPE_MARKER:
      return "marker";
    default:
      return "other";
  }
}

const char* severityName(GLenum severity) {
  switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH:
      return "high";
    case GL_DEBUG_SEVERITY_MEDIUM:
      return "medium";
    case GL_DEBUG_SEVERITY_LOW:
      return "low";
    default:
      return "notification";
  }
}

// Synchronous output: called on the thread of the GL call that caused it. Never throws (it
// returns into the driver); errors are kept for checkErrors instead.
void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                               const GLchar* message, const void*) {
  std::string text = length >= 0 ? std::string(message, size_t(length)) : std::string(message);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  std::fprintf(stderr, "hemirad: GL debug: %s (%s, id %u): %s\n", typeName(type), severityName(severity), id,
               text.c_str());
  // API errors are the ones glGetError also reports (a shader's compile log is thrown elsewhere).
  if (type == GL_DEBUG_TYPE_ERROR && source == GL_DEBUG_SOURCE_API && firstError.empty()) firstError = text;
}
}  // namespace

const char* errorName(unsigned error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    default:
      return "unknown GL error";
  }
}

void enableDebugOutput() {
  if (!glDebugMessageCallback || !glDebugMessageControl) {
    std::fprintf(stderr,
                 "hemirad: warning: --gl-debug: no KHR_debug in this context; GL errors are only checked "
                 "at pass ends, without the driver's messages\n");
    return;
  }
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  // Low-severity messages start disabled (KHR_debug); turn every source, type and severity on.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

void disableDebugOutput() {
  if (glDebugMessageCallback) glDebugMessageCallback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT);
}

void insertDebugMessage(unsigned id, bool marker, const char* text) {
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, marker ? GL_DEBUG_TYPE_MARKER : GL_DEBUG_TYPE_OTHER, id,
                       marker ? GL_DEBUG_SEVERITY_NOTIFICATION : GL_DEBUG_SEVERITY_LOW, -1, text);
}

unsigned takeError() { return glGetError(); }

std::string takeDebugError() { return std::exchange(firstError, std::string()); }

void checkErrors(std::string_view where) {
  GLenum e = glGetError();
  std::string detail = takeDebugError();
  if (e != GL_NO_ERROR)
    throw Error(
        fmt::format("GL error 0x{:04x} ({}) in {}{}", e, errorName(e), where, detail.empty() ? "" : ": " + detail));
  if (!detail.empty()) throw Error(fmt::format("GL error in {}: {}", where, detail));
}

}  // namespace hemirad::gl
