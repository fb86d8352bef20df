#include "gl/Shader.h"
#include "gl/ProgramPool.h"

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

#include "gl/Backend.h"
#include "gl/EmbeddedShaders.h"

namespace hemirad::gl {

namespace {

// HEMIRAD_SHADER_DIR, when set, is searched first: shader work without a rebuild.
std::string fileText(const std::string& name) {
  if (const char* dir = std::getenv("HEMIRAD_SHADER_DIR")) {
    std::ifstream in(std::string(dir) + "/" + name);
    if (in) return std::string(std::istreambuf_iterator<char>(in), {});
  }
  const std::string* text = embeddedShader(name);
  if (!text) throw Error(fmt::format("shader file '{}' is not in shaders/", name));
  return *text;
}

// Appends `name` with its includes expanded; `#line L N` maps driver lines back to files.
void expand(const std::string& name, std::vector<std::string>& names, std::string& out, int depth) {
  if (depth > 8) throw Error(fmt::format("shader include nesting too deep at '{}'", name));
  int index = static_cast<int>(names.size());
  names.push_back(name);
  out += fmt::format("#line 1 {}\n", index);
  std::istringstream in(fileText(name));
  std::string line;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (line.rfind("#include", 0) == 0) {
      auto a = line.find('"'), b = line.rfind('"');
      if (a == std::string::npos || b <= a) throw Error(fmt::format("{}:{}: malformed #include", name, lineNo));
      expand(line.substr(a + 1, b - a - 1), names, out, depth + 1);
      out += fmt::format("#line {} {}\n", lineNo + 1, index);
    } else {
      out += line;
      out += '\n';
    }
  }
}

// The info log of a shader or program (getiv/getLog: glGetShaderiv/glGetShaderInfoLog or the program pair).
template <class GetIv, class GetLog>
std::string infoLog(GLuint object, GetIv getiv, GetLog getLog) {
  GLint length = 0;
  getiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
  getLog(object, length, nullptr, log.data());
  return log.c_str();
}

std::string legend(const std::vector<std::string>& names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += fmt::format("{}{}={}", i ? ", " : "", i, names[i]);
  return s;
}

// A stage's source as the driver sees it, and the files its #line numbers name.
struct StageSource {
  std::string text;
  std::vector<std::string> names;
};
StageSource stageSource(const std::string& file, const Defines& defines) {
  StageSource s;
  s.text = shaderSource(file, defines, &s.names);
  return s;
}

GLuint compile(GLenum stage, const std::string& file, const StageSource& source) {
  const std::vector<std::string>& names = source.names;
  GLuint shader = glCreateShader(stage);
  const char* text = source.text.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::string log = infoLog(shader, glGetShaderiv, glGetShaderInfoLog);
    glDeleteShader(shader);
    throw Error(fmt::format("shader {} failed to compile (source numbers: {}):\n{}", file, legend(names), log));
  }
  return shader;
}

Program link(std::initializer_list<GLuint> shaders, const std::string& what) {
  GLuint program = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(program, s);
  glLinkProgram(program);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::string log = infoLog(program, glGetProgramiv, glGetProgramInfoLog);
    glDeleteProgram(program);
    throw Error(fmt::format("program {} failed to link:\n{}", what, log));
  }
  return Program(program);
}

}  // namespace

std::string shaderSource(const std::string& file, const Defines& defines, std::vector<std::string>* sourceNames) {
  std::string out = "#version 450 core\n";
  for (const auto& [name, value] : defines) out += fmt::format("#define {} {}\n", name, value);
  std::vector<std::string> names;
  expand(file, names, out, 0);
  if (sourceNames) *sourceNames = std::move(names);
  return out;
}

void checkCompiles(const std::string& file, const Defines& defines) {
  const auto endsWith = [&](const char* ext) { return file.ends_with(ext); };
  const GLenum stage = endsWith(".comp")   ? GL_COMPUTE_SHADER
                       : endsWith(".vert") ? GL_VERTEX_SHADER
                       : endsWith(".frag") ? GL_FRAGMENT_SHADER
                                           : 0;
  if (!stage) throw Error(fmt::format("shader {}: not a stage (.comp, .vert or .frag)", file));
  glDeleteShader(compile(stage, file, stageSource(file, defines)));
}

Program computeProgram(const std::string& file, const Defines& defines) {
  const StageSource source = stageSource(file, defines);  // the pool's key too
  if (GLuint id = takeProgram(source.text)) return Program(id);
  Program p = link({compile(GL_COMPUTE_SHADER, file, source)}, file);
  poolProgram(p.id(), source.text);
  return p;
}

Program renderProgram(const std::string& vertexFile, const std::string& fragmentFile, const Defines& defines) {
  const StageSource vertex = stageSource(vertexFile, defines), fragment = stageSource(fragmentFile, defines);
  const std::string key = vertex.text + fragment.text;
  if (GLuint id = takeProgram(key)) return Program(id);
  GLuint vs = compile(GL_VERTEX_SHADER, vertexFile, vertex);
  GLuint fs;
  try {
    fs = compile(GL_FRAGMENT_SHADER, fragmentFile, fragment);
  } catch (...) {
    glDeleteShader(vs);
    throw;
  }
  Program p = link({vs, fs}, vertexFile + "+" + fragmentFile);
  poolProgram(p.id(), key);
  return p;
}

}  // namespace hemirad::gl
