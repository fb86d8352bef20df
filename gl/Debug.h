#pragma once
#include <string>
#include <string_view>

namespace hemirad::gl {
// KHR_debug (--gl-debug): every message the driver sends, of every severity, is printed on stderr
// as `hemirad: GL debug: ...`; the first error message is kept for the next checkErrors.
void enableDebugOutput();
// Throws gl::Error naming `where` if glGetError reports an error (cheap checks at pass ends),
// with the KHR_debug message that explained it when debug output is on.
void checkErrors(std::string_view where);
// The first KHR_debug API error message since the last call (empty if none, or debug output is off).
std::string takeDebugError();
// Turns the output enableDebugOutput turned on off again.
void disableDebugOutput();
// A message of the application's own through KHR_debug: low severity of type other, or a
// notification of type marker (tests of the output).
void insertDebugMessage(unsigned id, bool marker, const char* text);
// glGetError's pending code (0: none), which it clears.
unsigned takeError();
// GL_INVALID_ENUM and friends by name.
const char* errorName(unsigned error);
}  // namespace hemirad::gl
