// Programs built from shaders/ (embedded at build time). Files carry no #version: the loader
// prepends `#version 450 core`, the defines and `#line`, and expands `#include "x.glsl"`, so
// driver logs point at real file lines; a failure names the files and carries the driver log.
// Files in $HEMIRAD_SHADER_DIR, if set, replace the embedded ones (edit shaders without a rebuild).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "gl/Objects.h"

namespace hemirad::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;

Program computeProgram(const std::string& file, const Defines& defines = {});
Program renderProgram(const std::string& vertexFile, const std::string& fragmentFile, const Defines& defines = {});

// Compiles one stage (.comp, .vert or .frag, by its extension) without linking: throws gl::Error
// with the driver's log if it fails (for tests that check every shader).
void checkCompiles(const std::string& file, const Defines& defines);

// The expanded source as the driver sees it (exposed for tests and error messages).
std::string shaderSource(const std::string& file, const Defines& defines,
                         std::vector<std::string>* sourceNames = nullptr);

}  // namespace hemirad::gl
