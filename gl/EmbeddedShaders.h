#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace hemirad::gl {
// Source of shaders/<name>, embedded at build time (cmake/EmbedShaders.cmake); nullptr if absent.
const std::string* embeddedShader(std::string_view name);
std::vector<std::string> embeddedShaderNames();  // sorted
}  // namespace hemirad::gl
