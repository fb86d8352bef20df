#include "gl/Objects.h"
#include "gl/ProgramPool.h"
#include "gl/StoragePool.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <string>

#include "gl/Backend.h"
#include "gl/Debug.h"
#include "gl/Limits.h"

namespace hemirad::gl {

namespace {
std::string formatBytes(double bytes) {
  return bytes >= 1 << 30 ? fmt::format("{:.2f} GiB", bytes / (1 << 30)) : fmt::format("{:.1f} MiB", bytes / (1 << 20));
}

// The texture formats hemirad allocates: name, bytes a texel, and the glClearTexImage format and
// type that zero one (a pooled texture handed out again, StoragePool.h).
struct TextureFormat {
  GLenum internal;
  const char* name;
  int bytes;
  GLenum zeroFormat, zeroType;
};
constexpr TextureFormat kTextureFormats[] = {
    {GL_RGBA32F, "GL_RGBA32F", 16, GL_RGBA, GL_FLOAT},
    {GL_R32UI, "GL_R32UI", 4, GL_RED_INTEGER, GL_UNSIGNED_INT},
    {GL_R32F, "GL_R32F", 4, GL_RGBA, GL_FLOAT},
    {GL_DEPTH_COMPONENT32F, "GL_DEPTH_COMPONENT32F", 4, GL_DEPTH_COMPONENT, GL_FLOAT},
    {GL_RGBA8, "GL_RGBA8", 4, GL_RGBA, GL_FLOAT},
};

// Its entry, or null for another format (then 16 bytes a texel are counted, and it is not pooled).
const TextureFormat* textureFormat(GLenum f) {
  for (const TextureFormat& t : kTextureFormats)
    if (t.internal == f) return &t;
  return nullptr;
}

// Storage allocation is where a GPU runs out of memory: GL_OUT_OF_MEMORY (or any error) there is
// thrown at once, naming the allocation, instead of surfacing later as garbage.
void checkAllocation(const std::function<std::string()>& what) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  std::string detail = takeDebugError();
  if (!detail.empty()) detail = ": " + detail;
  if (e == GL_OUT_OF_MEMORY) throw Error(fmt::format("out of GPU memory allocating {}{}", what(), detail));
  throw Error(fmt::format("GL error 0x{:04x} ({}) allocating {}{}", e, errorName(e), what(), detail));
}

// Fresh storage: `create` makes it in `id`; refused (out of memory), it is tried once more after
// the idle pool's storage (StoragePool.h) is given back to the driver.
void allocate(GLuint& id, bool texture, const std::function<void()>& create, const std::function<std::string()>& what) {
  create();
  try {
    checkAllocation(what);
  } catch (const Error&) {
    texture ? glDeleteTextures(1, &id) : glDeleteBuffers(1, &id);
    id = 0;
    if (!dropIdleStorage()) throw;
    create();
    checkAllocation(what);
  }
}
}  // namespace

namespace {
std::atomic<std::size_t> allocated{0}, peak{0};  // the viewer allocates on its worker thread
}  // namespace

std::size_t allocatedBytes() { return allocated.load(); }
std::size_t peakAllocatedBytes() { return peak.load(); }
void resetPeakAllocatedBytes() { peak.store(allocated.load()); }

Allocation::Allocation(std::size_t bytes) : bytes_(bytes) {
  const std::size_t now = allocated += bytes;
  std::size_t most = peak.load();
  while (now > most && !peak.compare_exchange_weak(most, now)) {
  }
}
Allocation::~Allocation() { allocated -= bytes_; }
Allocation& Allocation::operator=(Allocation&& o) noexcept {
  if (this != &o) {
    allocated -= bytes_;
    bytes_ = std::exchange(o.bytes_, 0);
  }
  return *this;
}

void deleteBuffer(GLuint id) {
  if (!returnStorage(id, false)) glDeleteBuffers(1, &id);
}
bool isBuffer(GLuint id) { return glIsBuffer(id) == GL_TRUE; }
bool isTexture(GLuint id) { return glIsTexture(id) == GL_TRUE; }
void deleteTexture(GLuint id) {
  if (!returnStorage(id, true)) glDeleteTextures(1, &id);
}
void deleteFramebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
void deleteProgram(GLuint id) {
  if (!returnProgram(id)) glDeleteProgram(id);
}
void deleteQuery(GLuint id) { glDeleteQueries(1, &id); }
void deleteVertexArray(GLuint id) { glDeleteVertexArrays(1, &id); }

// NVIDIA (H100, 2026-12-06): on storage the pool hands out again, an upload that follows its
// clear can be overtaken by it. A solver's control block, cleared and then given its header, came
// out with a header that shot nothing, and the solve ran forever (docs/adaptive.md, the stall);
// uploading zeros instead of the clear, or waiting for the clear, cured it, and fresh storage
// never showed it. So a pooled object's clear is waited for (at a solver's setup: the GPU is idle).
namespace {
void awaitPooledClear() { glFinish(); }
}  // namespace

// ---- Buffer
Buffer::Buffer(std::size_t bytes, const void* data) : size_(bytes) {
  const StorageShape shape{0, bytes};
  const bool pooled = (id_ = takeStorage(shape)) != 0;
  if (pooled) {
    if (data) upload(0, bytes, data);
  } else {
    allocate(
        id_, false,
        [&] {
          glCreateBuffers(1, &id_);
          glNamedBufferStorage(id_, static_cast<GLsizeiptr>(bytes ? bytes : 4), data, GL_DYNAMIC_STORAGE_BIT);
        },
        [&] { return fmt::format("a buffer of {} bytes ({})", bytes, formatBytes(double(bytes))); });
    poolStorage(id_, shape);
  }
  // Without data: zeros. GL leaves fresh storage undefined (a driver may back it with memory a
  // deleted object of this process held), and pooled storage holds its last owner's.
  if (!data) {
    glClearNamedBufferData(id_, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    if (pooled) awaitPooledClear();
  }
  allocation_ = Allocation(bytes);
}
void Buffer::upload(std::size_t offset, std::size_t bytes, const void* data) {
  glNamedBufferSubData(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}
void Buffer::uploadAfterShaderWrites(std::size_t offset, std::size_t bytes, const void* data) {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  upload(offset, bytes, data);
}
void Buffer::read(std::size_t offset, std::size_t bytes, void* out) const {
  glGetNamedBufferSubData(id_, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), out);
}
void Buffer::bindBase(GLenum target, GLuint index) const {
  // Past the limit a shader would read garbage, not fail: refused by name instead.
  if (target == GL_SHADER_STORAGE_BUFFER) requireStorageBlock(size_, fmt::format("shader storage binding {}", index));
  glBindBufferBase(target, index, id_);
}
void Buffer::bind(GLenum target) const { glBindBuffer(target, id_); }
void Buffer::clear(float value) { glClearNamedBufferData(id_, GL_R32F, GL_RED, GL_FLOAT, &value); }
void Buffer::clear(std::uint32_t value) {
  glClearNamedBufferData(id_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &value);
}
void Buffer::copyTo(Buffer& destination, std::size_t from, std::size_t to, std::size_t bytes) const {
  glCopyNamedBufferSubData(id_, destination.id_, static_cast<GLintptr>(from), static_cast<GLintptr>(to),
                           static_cast<GLsizeiptr>(bytes));
}

// ---- Texture
Texture::Texture(GLenum internalFormat, int width, int height, int layers)
    : width_(width), height_(height), layers_(layers), format_(internalFormat) {
  const TextureFormat* known = textureFormat(internalFormat);
  const std::string name = known ? known->name : fmt::format("format 0x{:04x}", internalFormat);
  const std::size_t bytes = std::size_t(known ? known->bytes : 16) * std::size_t(width) * std::size_t(height) *
                            std::size_t(std::max(layers, 1));
  const StorageShape shape{internalFormat, bytes, width, height, layers};
  const bool pooled = known && (id_ = takeStorage(shape)) != 0;
  if (!pooled) {
    allocate(
        id_, true,
        [&] {
          glCreateTextures(layers ? GL_TEXTURE_2D_ARRAY : GL_TEXTURE_2D, 1, &id_);
          if (layers)
            glTextureStorage3D(id_, 1, internalFormat, width, height, layers);
          else
            glTextureStorage2D(id_, 1, internalFormat, width, height);
        },
        [&] {
          return fmt::format("a {} x {}{} {} texture ({})", width, height, layers ? fmt::format(" x {}", layers) : "",
                             name, formatBytes(double(bytes)));
        });
    if (known) poolStorage(id_, shape);
  }
  if (known) {
    glClearTexImage(id_, 0, known->zeroFormat, known->zeroType, nullptr);  // zeros, as a Buffer's
    if (pooled) awaitPooledClear();
  }
  allocation_ = Allocation(bytes);
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // (a pooled one may have been linearFiltering'd)
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}
Texture::Texture(GLenum internalFormat, int width, int height, Samples samples)
    : width_(width), height_(height), format_(internalFormat) {
  const TextureFormat* known = textureFormat(internalFormat);
  const std::size_t bytes =
      std::size_t(known ? known->bytes : 16) * std::size_t(width) * std::size_t(height) * std::size_t(samples.count);
  allocate(
      id_, true,
      [&] {
        glCreateTextures(GL_TEXTURE_2D_MULTISAMPLE, 1, &id_);
        glTextureStorage2DMultisample(id_, samples.count, internalFormat, width, height, GL_TRUE);
        glGetTextureLevelParameteriv(id_, 0, GL_TEXTURE_SAMPLES, &samples_);
      },
      [&] {
        return fmt::format("a {} x {} x {}-sample {} texture ({})", width, height, samples.count,
                           known ? known->name : "", formatBytes(double(bytes)));
      });
  allocation_ = Allocation(bytes);
}
void Texture::upload(GLenum format, GLenum type, const void* data) {
  glTextureSubImage2D(id_, 0, 0, 0, width_, height_, format, type, data);
}
void Texture::read(GLenum format, GLenum type, std::size_t bytes, void* out) const {
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id_, 0, format, type, static_cast<GLsizei>(bytes), out);
}
void Texture::bindUnit(GLuint unit) const { glBindTextureUnit(unit, id_); }
void Texture::linearFiltering() {
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}
void Texture::bindImage(GLuint unit, GLenum access) const {
  glBindImageTexture(unit, id_, 0, GL_FALSE, 0, access, format_);
}
void Texture::clear(float value) { glClearTexImage(id_, 0, GL_RED, GL_FLOAT, &value); }
void Texture::clear(std::uint32_t value) { glClearTexImage(id_, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &value); }

// ---- Framebuffer
Framebuffer::Framebuffer() { glCreateFramebuffers(1, &id_); }
void Framebuffer::attach(GLenum attachment, const Texture& texture) {
  glNamedFramebufferTexture(id_, attachment, texture.id(), 0);
}
void Framebuffer::checkComplete(const char* what) const {
  GLenum status = glCheckNamedFramebufferStatus(id_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) throw Error(fmt::format("{} framebuffer incomplete (0x{:04x})", what, status));
}
void Framebuffer::bind() const { glBindFramebuffer(GL_FRAMEBUFFER, id_); }
// Clears cover the whole attachment: a pass drawn in bands (src/output/DrawBands.h) leaves its
// scissor on, which they would honour.
void Framebuffer::clearColor(float r, float g, float b, float a) {
  glDisable(GL_SCISSOR_TEST);
  const float v[4] = {r, g, b, a};
  glClearNamedFramebufferfv(id_, GL_COLOR, 0, v);
}
void Framebuffer::clearColor(std::uint32_t value) {
  glDisable(GL_SCISSOR_TEST);
  const GLuint v[4] = {value, 0, 0, 0};
  glClearNamedFramebufferuiv(id_, GL_COLOR, 0, v);
}
void Framebuffer::clearDepth(float depth) {
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);  // clears honour the depth mask, which a depth-equal pass may have left off
  glClearNamedFramebufferfv(id_, GL_DEPTH, 0, &depth);
}

// ---- VertexArray
VertexArray::VertexArray() { glCreateVertexArrays(1, &id_); }
void VertexArray::vertexBuffer(const Buffer& buffer, GLsizei stride) {
  glVertexArrayVertexBuffer(id_, 0, buffer.id(), 0, stride);
}
void VertexArray::floatAttribute(GLuint location, GLint components, GLuint offset) {
  glEnableVertexArrayAttrib(id_, location);
  glVertexArrayAttribFormat(id_, location, components, GL_FLOAT, GL_FALSE, offset);
  glVertexArrayAttribBinding(id_, location, 0);
}
void VertexArray::uintAttribute(GLuint location, GLuint offset) {
  glEnableVertexArrayAttrib(id_, location);
  glVertexArrayAttribIFormat(id_, location, 1, GL_UNSIGNED_INT, offset);
  glVertexArrayAttribBinding(id_, location, 0);
}
void VertexArray::instanceUintAttribute(GLuint location, const Buffer& buffer) {
  glVertexArrayVertexBuffer(id_, 1, buffer.id(), 0, sizeof(GLuint));
  glVertexArrayBindingDivisor(id_, 1, 1);
  glEnableVertexArrayAttrib(id_, location);
  glVertexArrayAttribIFormat(id_, location, 1, GL_UNSIGNED_INT, 0);
  glVertexArrayAttribBinding(id_, location, 1);
}
void VertexArray::indexBuffer(const Buffer& buffer) { glVertexArrayElementBuffer(id_, buffer.id()); }
void VertexArray::bind() const { glBindVertexArray(id_); }

// ---- Query
Query::Query(GLenum target) { glCreateQueries(target, 1, &id_); }
bool Query::available() const {
  GLuint ready = GL_FALSE;
  glGetQueryObjectuiv(id_, GL_QUERY_RESULT_AVAILABLE, &ready);
  return ready == GL_TRUE;
}
std::uint64_t Query::result() const {
  GLuint64 v = 0;
  glGetQueryObjectui64v(id_, GL_QUERY_RESULT, &v);
  return v;
}

// ---- Program
void Program::use() const { glUseProgram(id_); }
GLint Program::location(const char* uniform) const { return glGetUniformLocation(id_, uniform); }
void Program::set(const char* uniform, int v) const { glProgramUniform1i(id_, location(uniform), v); }
void Program::set(const char* uniform, unsigned v) const { glProgramUniform1ui(id_, location(uniform), v); }
void Program::set(const char* uniform, float v) const { glProgramUniform1f(id_, location(uniform), v); }
void Program::set(const char* uniform, const float* mat4) const {
  glProgramUniformMatrix4fv(id_, location(uniform), 1, GL_FALSE, mat4);
}
void Program::set(const char* uniform, int x, int y) const { glProgramUniform2i(id_, location(uniform), x, y); }
void Program::set(const char* uniform, float x, float y, float z) const {
  glProgramUniform3f(id_, location(uniform), x, y, z);
}
void Program::set(const char* uniform, std::span<const unsigned> values) const {
  glProgramUniform1uiv(id_, location(uniform), GLsizei(values.size()), values.data());
}
void Program::dispatch(unsigned x, unsigned y, unsigned z) { glDispatchCompute(x, y, z); }

}  // namespace hemirad::gl
