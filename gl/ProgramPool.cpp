#include "gl/ProgramPool.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <list>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace hemirad::gl {

namespace {

// A uniform's value as linked: `words` 32-bit components read as float, int or uint.
struct Uniform {
  GLint location;
  GLenum type;
  GLint components;
  char kind;  // 'f', 'i' or 'u'
  std::vector<std::uint32_t> words;
};

// Components and base kind of the uniform types hemirad's shaders declare; 0 for any other,
// whose program is then not pooled.
GLint componentsOf(GLenum type, char& kind) {
  kind = 'f';
  switch (type) {
    case GL_FLOAT:
      return 1;
    case GL_FLOAT_VEC2:
      return 2;
    case GL_FLOAT_VEC3:
      return 3;
    case GL_FLOAT_VEC4:
      return 4;
    case GL_FLOAT_MAT4:
      return 16;
    case GL_UNSIGNED_INT:
      kind = 'u';
      return 1;
    case GL_UNSIGNED_INT_VEC2:
      kind = 'u';
      return 2;
    case GL_UNSIGNED_INT_VEC3:
      kind = 'u';
      return 3;
    case GL_UNSIGNED_INT_VEC4:
      kind = 'u';
      return 4;
    case GL_INT:
    case GL_BOOL:
      kind = 'i';
      return 1;
    case GL_INT_VEC2:
      kind = 'i';
      return 2;
    case GL_INT_VEC3:
      kind = 'i';
      return 3;
    case GL_INT_VEC4:
      kind = 'i';
      return 4;
    default:
      break;
  }
  // Samplers and images: their unit, an int (layout(binding = N) sets it at link).
  const bool sampler = (type >= GL_SAMPLER_1D && type <= GL_SAMPLER_2D_SHADOW) ||
                       (type >= GL_SAMPLER_1D_ARRAY && type <= GL_UNSIGNED_INT_SAMPLER_BUFFER) ||
                       (type >= GL_IMAGE_1D && type <= GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY);
  kind = 'i';
  return sampler ? 1 : 0;
}

// Every default-block uniform's value, element by element; false if a type is not handled.
bool noteUniforms(GLuint id, std::vector<Uniform>& out) {
  GLint count = 0, longest = 0;
  glGetProgramiv(id, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(id, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  for (GLint i = 0; i < count; ++i) {
    std::string name(std::size_t(longest) + 1, '\0');
    GLint size = 0, length = 0;
    GLenum type = 0;
    glGetActiveUniform(id, GLuint(i), GLsizei(name.size()), &length, &size, &type, name.data());
    name.resize(std::size_t(length));
    if (glGetUniformLocation(id, name.c_str()) < 0) continue;  // a block member: its buffer holds it
    char kind = 'f';
    const GLint components = componentsOf(type, kind);
    if (components == 0) return false;
    const std::string base = name.ends_with("[0]") ? name.substr(0, name.size() - 3) : name;
    for (GLint e = 0; e < size; ++e) {
      const GLint location =
          glGetUniformLocation(id, size > 1 ? (base + "[" + std::to_string(e) + "]").c_str() : name.c_str());
      if (location < 0) continue;
      Uniform u{location, type, components, kind, std::vector<std::uint32_t>(std::size_t(components))};
      if (kind == 'f') glGetUniformfv(id, u.location, reinterpret_cast<GLfloat*>(u.words.data()));
      if (kind == 'i') glGetUniformiv(id, u.location, reinterpret_cast<GLint*>(u.words.data()));
      if (kind == 'u') glGetUniformuiv(id, u.location, u.words.data());
      out.push_back(std::move(u));
    }
  }
  return true;
}

void restore(GLuint id, const Uniform& u) {
  const auto* f = reinterpret_cast<const GLfloat*>(u.words.data());
  const auto* i = reinterpret_cast<const GLint*>(u.words.data());
  const GLuint* w = u.words.data();
  if (u.type == GL_FLOAT_MAT4) return glProgramUniformMatrix4fv(id, u.location, 1, GL_FALSE, f);
  switch (u.kind == 'f' ? u.components : u.kind == 'i' ? 10 + u.components : 20 + u.components) {
    case 1:
      return glProgramUniform1fv(id, u.location, 1, f);
    case 2:
      return glProgramUniform2fv(id, u.location, 1, f);
    case 3:
      return glProgramUniform3fv(id, u.location, 1, f);
    case 4:
      return glProgramUniform4fv(id, u.location, 1, f);
    case 11:
      return glProgramUniform1iv(id, u.location, 1, i);
    case 12:
      return glProgramUniform2iv(id, u.location, 1, i);
    case 13:
      return glProgramUniform3iv(id, u.location, 1, i);
    case 14:
      return glProgramUniform4iv(id, u.location, 1, i);
    case 21:
      return glProgramUniform1uiv(id, u.location, 1, w);
    case 22:
      return glProgramUniform2uiv(id, u.location, 1, w);
    case 23:
      return glProgramUniform3uiv(id, u.location, 1, w);
    case 24:
      return glProgramUniform4uiv(id, u.location, 1, w);
    default:
      return;
  }
}

struct Pooled {
  std::string key;
  std::vector<Uniform> linked;
};

struct Pool {
  std::mutex mutex;
  bool open = false;
  std::unordered_map<GLuint, Pooled> known;  // every pooled program, idle or owned
  std::list<GLuint> idle;                    // oldest first
};

// Past this many idle programs the oldest is deleted: a process that walks through many
// configurations (a sweep, the viewer loading scene after scene) keeps the recent ones.
constexpr std::size_t kMostIdle = 64;

Pool& pool() {
  static Pool p;
  return p;
}

}  // namespace

GLuint takeProgram(const std::string& key) {
  Pool& p = pool();
  std::lock_guard lock(p.mutex);
  auto it = std::find_if(p.idle.rbegin(), p.idle.rend(), [&](GLuint id) { return p.known.at(id).key == key; });
  if (!p.open || it == p.idle.rend()) return 0;
  const GLuint id = *it;
  p.idle.erase(std::next(it).base());
  for (const Uniform& u : p.known.at(id).linked) restore(id, u);
  return id;
}

void poolProgram(GLuint id, const std::string& key) {
  Pool& p = pool();
  std::lock_guard lock(p.mutex);
  std::vector<Uniform> linked;
  if (p.open && noteUniforms(id, linked)) p.known[id] = {key, std::move(linked)};
}

bool returnProgram(GLuint id) {
  Pool& p = pool();
  std::lock_guard lock(p.mutex);
  auto it = p.known.find(id);
  if (!p.open || it == p.known.end()) return false;
  p.idle.push_back(id);
  if (p.idle.size() > kMostIdle) {
    glDeleteProgram(p.idle.front());
    p.known.erase(p.idle.front());
    p.idle.pop_front();
  }
  return true;
}

void openProgramPool() {
  Pool& p = pool();
  std::lock_guard lock(p.mutex);
  p.open = true;
}

void closeProgramPool() {
  Pool& p = pool();
  std::lock_guard lock(p.mutex);
  for (GLuint id : p.idle) glDeleteProgram(id);
  p.idle.clear();
  p.known.clear();  // programs still owned are deleted by their owners (returnProgram: false)
  p.open = false;
}

std::size_t idlePrograms() {
  Pool& p = pool();
  std::lock_guard lock(p.mutex);
  return p.idle.size();
}

}  // namespace hemirad::gl
