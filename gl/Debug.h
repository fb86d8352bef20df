#pragma once
#include <string_view>

namespace hemirad::gl {
// KHR_debug: GL errors become exceptions at the call that caused them (debug contexts only).
void enableDebugOutput();
// Throws gl::Error naming `where` if glGetError reports an error (cheap checks at pass ends).
void checkErrors(std::string_view where);
}  // namespace hemirad::gl
