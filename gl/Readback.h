// Small reads of GPU-written buffers that do not drain the queue: copy() enqueues a copy into the
// next slot of a persistently mapped ring and fences it; wait() hands back the oldest pending
// copy once its fence has signalled. Commands enqueued after copy() keep the GPU busy while the
// CPU waits, which a glGetBufferSubData (it waits for everything before it) would not allow.
#pragma once
#include <cstddef>
#include <vector>

#include "gl/Objects.h"

namespace hemirad::gl {

class Readback {
 public:
  Readback() = default;
  Readback(std::size_t bytes, unsigned slots);
  ~Readback();
  Readback(const Readback&) = delete;
  Readback& operator=(const Readback&) = delete;
  Readback(Readback&&) noexcept;
  Readback& operator=(Readback&&) noexcept;
  // Enqueues a copy of `from`'s first bytes() bytes; at most slots() may be pending.
  void copy(const Buffer& from);
  unsigned pending() const { return pending_; }
  // The oldest pending copy's bytes (valid until the next copy() into its slot).
  const void* wait();
  std::size_t bytes() const { return bytes_; }

 private:
  void release();
  GLuint buffer_ = 0;
  const std::byte* mapped_ = nullptr;
  std::size_t bytes_ = 0, stride_ = 0;
  std::vector<GLsync> fences_;
  unsigned next_ = 0, pending_ = 0;
  Allocation allocation_;
};

}  // namespace hemirad::gl
