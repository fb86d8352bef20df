#include "gl/StoragePool.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <list>
#include <mutex>
#include <unordered_map>

namespace hemirad::gl {

namespace {

// Buffer and texture names are separate namespaces: a key carries which.
std::uint64_t keyOf(GLuint id, bool texture) { return std::uint64_t(id) | (std::uint64_t(texture) << 32); }
GLuint idOf(std::uint64_t key) { return GLuint(key); }
bool isTextureKey(std::uint64_t key) { return (key >> 32) != 0; }

struct StoragePool {
  std::mutex mutex;
  bool open = false;
  std::unordered_map<std::uint64_t, StorageShape> known;  // every pooled object, idle or owned
  std::list<std::uint64_t> idle;                          // oldest first
  std::size_t idleBytes = 0;
};

// Past either cap the oldest idle objects are deleted: a process that walks through scenes of
// many sizes (a bench's rows, the viewer) keeps the recent ones, and idle storage never holds
// more than a large solve's own (bench --elements 1000000 allocates ~94 MiB).
constexpr std::size_t kMostIdleStorage = 256;
constexpr std::size_t kMostIdleBytes = std::size_t(1) << 30;

StoragePool& storagePool() {
  static StoragePool p;
  return p;
}

void destroy(std::uint64_t key) {
  const GLuint id = idOf(key);
  if (isTextureKey(key))
    glDeleteTextures(1, &id);
  else
    glDeleteBuffers(1, &id);
}

// The oldest idle object leaves the pool and the context (the mutex held).
void dropOldest(StoragePool& p) {
  const std::uint64_t key = p.idle.front();
  p.idle.pop_front();
  p.idleBytes -= p.known.at(key).bytes;
  p.known.erase(key);
  destroy(key);
}

}  // namespace

GLuint takeStorage(const StorageShape& shape) {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  const bool texture = shape.format != 0;
  auto it = std::find_if(p.idle.rbegin(), p.idle.rend(),
                         [&](std::uint64_t key) { return isTextureKey(key) == texture && p.known.at(key) == shape; });
  if (!p.open || it == p.idle.rend()) return 0;
  const std::uint64_t key = *it;
  p.idle.erase(std::next(it).base());
  p.idleBytes -= shape.bytes;
  // Its last owner's shader writes (image stores, SSBOs) are incoherent: GL asks for a barrier
  // before a clear or an upload touches what they wrote (llvmpipe runs them in order; a GPU need
  // not). What an NVIDIA driver does besides: gl/Objects.cpp's awaitPooledClear.
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  return idOf(key);
}

void poolStorage(GLuint id, const StorageShape& shape) {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  if (p.open) p.known[keyOf(id, shape.format != 0)] = shape;
}

bool returnStorage(GLuint id, bool texture) {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  const std::uint64_t key = keyOf(id, texture);
  auto it = p.known.find(key);
  if (!p.open || it == p.known.end()) return false;
  p.idle.push_back(key);
  p.idleBytes += it->second.bytes;
  while (!p.idle.empty() && (p.idle.size() > kMostIdleStorage || p.idleBytes > kMostIdleBytes)) dropOldest(p);
  return true;
}

bool dropIdleStorage() {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  const bool any = !p.idle.empty();
  while (!p.idle.empty()) dropOldest(p);
  return any;
}

void openStoragePool() {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  p.open = true;
}

void closeStoragePool() {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  while (!p.idle.empty()) dropOldest(p);
  p.known.clear();  // objects still owned are deleted by their owners (returnStorage: false)
  p.open = false;
}

std::size_t idleStorageBytes() {
  StoragePool& p = storagePool();
  std::lock_guard lock(p.mutex);
  return p.idleBytes;
}

}  // namespace hemirad::gl
