// GL objects as move-only RAII handles (after Magnum's GL wrappers): copy is deleted, a move
// leaves the source empty (id 0), destruction deletes the name. All use GL 4.5 DSA.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>

#include "gl/GL.h"

namespace hemirad::gl {

template <void (*Delete)(GLuint)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(GLuint id) : id_(id) {}
  ~Handle() { reset(); }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }

 protected:
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }
  GLuint id_ = 0;
};

// Device bytes in live Buffers and Textures: what hemirad asked the driver for (its own
// overhead and a context's framebuffers not counted), reported per element by info and bench.
std::size_t allocatedBytes();
std::size_t peakAllocatedBytes();  // since the last reset
void resetPeakAllocatedBytes();    // the peak becomes what is allocated now

// Counts its bytes in allocatedBytes() while it lives; a move hands them on.
class Allocation {
 public:
  Allocation() = default;
  explicit Allocation(std::size_t bytes);
  ~Allocation();
  Allocation(Allocation&& o) noexcept : bytes_(std::exchange(o.bytes_, 0)) {}
  Allocation& operator=(Allocation&& o) noexcept;

 private:
  std::size_t bytes_ = 0;
};

void deleteBuffer(GLuint);
void deleteTexture(GLuint);
void deleteFramebuffer(GLuint);
void deleteProgram(GLuint);
void deleteQuery(GLuint);
void deleteVertexArray(GLuint);
// Whether `id` names a live object of that kind (the handles' ownership tests).
bool isBuffer(GLuint id);
bool isTexture(GLuint id);

class Buffer : public Handle<deleteBuffer> {
 public:
  Buffer() = default;
  // Immutable storage of `bytes`, optionally initialised; dynamic so it can be updated.
  Buffer(std::size_t bytes, const void* data = nullptr);
  template <class T>
  explicit Buffer(std::span<const T> data) : Buffer(data.size_bytes(), data.data()) {}
  std::size_t size() const { return size_; }
  void upload(std::size_t offset, std::size_t bytes, const void* data);
  // upload() into what shaders wrote: their writes are incoherent, and GL asks for a buffer-update
  // barrier before an upload touches them (a solver's control block after its passes).
  void uploadAfterShaderWrites(std::size_t offset, std::size_t bytes, const void* data);
  void read(std::size_t offset, std::size_t bytes, void* out) const;
  void bindBase(GLenum target, GLuint index) const;  // SSBO / UBO binding point
  void bind(GLenum target) const;                    // e.g. GL_DISPATCH_INDIRECT_BUFFER
  void clear(float value);                           // every 32-bit word
  void clear(std::uint32_t value);
  void copyTo(Buffer& destination, std::size_t from, std::size_t to, std::size_t bytes) const;

 private:
  std::size_t size_ = 0;
  Allocation allocation_;
};

class Texture : public Handle<deleteTexture> {
 public:
  Texture() = default;
  // A single-level 2D texture with nearest filtering (texel elements are fetched exactly);
  // with `layers`, a 2D array texture.
  Texture(GLenum internalFormat, int width, int height, int layers = 0);
  // A multisampled 2D texture of `samples` samples a texel at the driver's fixed positions: a
  // render target only (read it through a sampler2DMS).
  struct Samples {
    int count;
  };
  Texture(GLenum internalFormat, int width, int height, Samples samples);
  int width() const { return width_; }
  int height() const { return height_; }
  GLenum format() const { return format_; }
  int samples() const { return samples_; }  // what the driver gave a multisampled one; else 1
  void upload(GLenum format, GLenum type, const void* data);
  void read(GLenum format, GLenum type, std::size_t bytes, void* out) const;
  void bindUnit(GLuint unit) const;
  // Bilinear filtering (GL_LINEAR, edges clamped): how engines sample a lightmap.
  void linearFiltering();
  void bindImage(GLuint unit, GLenum access) const;
  void clear(float value);          // a GL_R32F texture
  void clear(std::uint32_t value);  // a GL_R32UI texture

 private:
  int width_ = 0, height_ = 0, layers_ = 0, samples_ = 1;
  GLenum format_ = 0;
  Allocation allocation_;
};

class Framebuffer : public Handle<deleteFramebuffer> {
 public:
  Framebuffer();
  void attach(GLenum attachment, const Texture& texture);
  void checkComplete(const char* what) const;  // throws gl::Error
  // Colour attachment 0 (every layer of a layered one), and the depth attachment.
  void clearColor(float r, float g, float b, float a);
  void clearColor(std::uint32_t value);  // an integer attachment: (value, 0, 0, 0)
  void clearDepth(float depth);
  void bind() const;
};

class VertexArray : public Handle<deleteVertexArray> {
 public:
  VertexArray();
  // Vertex buffer binding 0: `buffer` with `stride`; attributes read from it.
  void vertexBuffer(const Buffer& buffer, GLsizei stride);
  void floatAttribute(GLuint location, GLint components, GLuint offset);
  void uintAttribute(GLuint location, GLuint offset);  // one GLuint, not normalised
  // Vertex buffer binding 1, advanced once per instance: attribute `location` is GLuint
  // `buffer[baseInstance + instance]` (an indirect draw's baseInstance picks the element).
  void instanceUintAttribute(GLuint location, const Buffer& buffer);
  void indexBuffer(const Buffer& buffer);  // GLuint indices (drawIndexedTriangles)
  void bind() const;
};

class Query : public Handle<deleteQuery> {
 public:
  Query() = default;
  explicit Query(GLenum target);  // GL_TIMESTAMP, GL_TIME_ELAPSED, GL_SAMPLES_PASSED...
  std::uint64_t result() const;   // waits if not yet available
  bool available() const;         // the result can be read without waiting
};

class Program : public Handle<deleteProgram> {
 public:
  Program() = default;
  explicit Program(GLuint linked) : Handle(linked) {}
  void use() const;
  GLint location(const char* uniform) const;  // -1 if the uniform was optimised away
  void set(const char* uniform, int v) const;
  void set(const char* uniform, unsigned v) const;
  void set(const char* uniform, float v) const;
  void set(const char* uniform, const float* mat4) const;
  void set(const char* uniform, int x, int y) const;                      // ivec2
  void set(const char* uniform, float x, float y, float z) const;         // vec3
  void set(const char* uniform, std::span<const unsigned> values) const;  // uint[]
  // Compute dispatch helpers (the program must be in use).
  static void dispatch(unsigned x, unsigned y = 1, unsigned z = 1);
};

inline unsigned groupsFor(unsigned items, unsigned groupSize) { return (items + groupSize - 1) / groupSize; }

}  // namespace hemirad::gl
