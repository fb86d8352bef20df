// Pipeline state and commands outside the objects (after Filament's Driver API): a pass states
// all of its raster state in one RasterState and applies it once, so no pass depends on what
// the one before it left enabled; barriers and draws take small typed enums, not GL bitfields.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>

#include "gl/GL.h"

namespace hemirad::gl {

class Buffer;

enum class DepthFunc : GLenum { Less = GL_LESS, Greater = GL_GREATER, Equal = GL_EQUAL, Always = GL_ALWAYS };

// Clip-space depth. Standard: [-1, 1], the item buffer's distance / far with GL_LESS. Reversed:
// [0, 1] with a depth buffer cleared to 0 and GL_GREATER, for camera views whose projection puts
// depth = near / distance (Camera::viewProjection): a float's spacing shrinks with its value, so
// the relative precision is ~1e-7 at every distance, and a light 0.5 mm below a ceiling seen from
// metres away wins its pixels ([-1, 1] loses that to rounding near 1).
enum class DepthRange { Standard, Reversed };

// Pixels from (x, y) (bottom-up) of a framebuffer.
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct RasterState {
  int width = 0, height = 0;  // the viewport, from the origin
  bool depthTest = true;
  DepthFunc depthFunc = DepthFunc::Less;
  DepthRange depthRange = DepthRange::Standard;
  bool depthWrite = true;
  bool cullFaces = false;                      // hemirad's faces occlude and are seen from both sides
  bool clipDistance0 = false;                  // gl_ClipDistance[0] (the item buffer's hemisphere)
  bool additiveBlend = false;                  // colour += fragment (instant radiosity sums VPL batches)
  std::optional<Rect> scissor = std::nullopt;  // draws only inside it
  void apply() const;
};

// A camera view's state: reversed depth, GL_GREATER; its depth buffer is cleared to 0 (infinity).
inline RasterState cameraView(int width, int height) {
  return {.width = width, .height = height, .depthFunc = DepthFunc::Greater, .depthRange = DepthRange::Reversed};
}

// glMemoryBarrier's bits: what later commands read that earlier shaders wrote.
enum class Barrier : GLbitfield {
  Storage = GL_SHADER_STORAGE_BARRIER_BIT,
  Image = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT,
  TextureFetch = GL_TEXTURE_FETCH_BARRIER_BIT,
  TextureUpdate = GL_TEXTURE_UPDATE_BARRIER_BIT,  // glGetTextureImage and uploads
  BufferUpdate = GL_BUFFER_UPDATE_BARRIER_BIT,    // buffer reads, copies and uploads
  Framebuffer = GL_FRAMEBUFFER_BARRIER_BIT,
  Command = GL_COMMAND_BARRIER_BIT,  // indirect commands
};
constexpr Barrier operator|(Barrier a, Barrier b) { return Barrier(GLbitfield(a) | GLbitfield(b)); }
void barrier(Barrier bits);

// Triangles from vertex 0 of the bound vertex array, `instances` times.
void drawTriangles(std::size_t vertices, int instances = 1);
// The same from the bound vertex array's GLuint index buffer: shared vertices are shaded once.
void drawIndexedTriangles(std::size_t indices, int instances = 1);
// Indexed triangles as `count` DrawElementsIndirectCommand records of `commands` (written by a
// shader: a Barrier::Command first), from the bound vertex array's index buffer.
void drawIndexedIndirect(const Buffer& commands, std::size_t count);
// Waits for every command enqueued so far (timing; synchronised readback is implicit).
void finish();

}  // namespace hemirad::gl
