#pragma once
#include <string>
#include <string_view>

namespace hemirad::gl {
// Source of shaders/<name>, embedded at build time (cmake/EmbedShaders.cmake); nullptr if absent.
const std::string* embeddedShader(std::string_view name);
}  // namespace hemirad::gl
