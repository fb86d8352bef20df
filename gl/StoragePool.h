// Buffer and texture storage outlives its owners, as linked programs do (ProgramPool.h). A driver
// maps fresh storage in at its first use, so a solver built again and again (bench rows, adaptive
// rounds, sweeps, the direct split) paid for its pages in its first passes. A Buffer or Texture
// destroyed goes back to this pool, keyed by its exact shape, and the next request of that shape
// takes it, cleared to zero (the clear waited for: gl/Objects.cpp's awaitPooledClear) and with
// nearest filtering, as fresh storage made without data is (cleared too: GL leaves it
// undefined). Idle storage is capped (kMostIdleBytes, oldest deleted first) and given back whole
// before a fresh allocation is retried on GL_OUT_OF_MEMORY. The pool lives with the context.
#pragma once
#include <cstddef>

#include "gl/GL.h"

namespace hemirad::gl {

// What a storage object is: a buffer of `bytes` (format 0), or a texture.
struct StorageShape {
  GLenum format = 0;  // a texture's internal format; 0: a buffer
  std::size_t bytes = 0;
  int width = 0, height = 0, layers = 0;
  bool operator==(const StorageShape&) const = default;
};

GLuint takeStorage(const StorageShape& shape);           // an idle object of this shape, or 0
void poolStorage(GLuint id, const StorageShape& shape);  // a fresh one, returned when its owner goes
bool returnStorage(GLuint id, bool texture);             // back to the pool; false: not pooled, delete it
bool dropIdleStorage();                                  // deletes the idle ones; false if there were none
void openStoragePool();                                  // a context is current (RenderBackend)
void closeStoragePool();                                 // deletes the idle ones before the context goes
std::size_t idleStorageBytes();

}  // namespace hemirad::gl
