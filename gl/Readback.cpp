#include "gl/Readback.h"

#include <stdexcept>
#include <utility>

namespace hemirad::gl {

Readback::Readback(std::size_t bytes, unsigned slots) : bytes_(bytes), stride_((bytes + 255) / 256 * 256) {
  fences_.assign(slots, nullptr);
  constexpr GLbitfield flags = GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
  glCreateBuffers(1, &buffer_);
  glNamedBufferStorage(buffer_, GLsizeiptr(stride_ * slots), nullptr, flags | GL_CLIENT_STORAGE_BIT);
  mapped_ = static_cast<const std::byte*>(glMapNamedBufferRange(buffer_, 0, GLsizeiptr(stride_ * slots), flags));
  if (!mapped_) throw std::runtime_error("GL: a persistently mapped readback buffer could not be made");
  allocation_ = Allocation(stride_ * slots);
}

Readback::~Readback() { release(); }

void Readback::release() {
  for (GLsync& f : fences_)
    if (f) glDeleteSync(std::exchange(f, nullptr));
  if (buffer_) {
    glUnmapNamedBuffer(buffer_);
    glDeleteBuffers(1, &buffer_);
  }
  buffer_ = 0;
}

Readback::Readback(Readback&& o) noexcept { *this = std::move(o); }
Readback& Readback::operator=(Readback&& o) noexcept {
  if (this == &o) return *this;
  release();
  buffer_ = std::exchange(o.buffer_, 0);
  mapped_ = std::exchange(o.mapped_, nullptr);
  bytes_ = o.bytes_, stride_ = o.stride_;
  fences_ = std::move(o.fences_);
  next_ = o.next_, pending_ = std::exchange(o.pending_, 0);
  allocation_ = std::move(o.allocation_);
  return *this;
}

void Readback::copy(const Buffer& from) {
  if (pending_ == fences_.size()) throw std::logic_error("Readback::copy: every slot is pending");
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_CLIENT_MAPPED_BUFFER_BARRIER_BIT);
  glCopyNamedBufferSubData(from.id(), buffer_, 0, GLintptr(next_ * stride_), GLsizeiptr(bytes_));
  fences_[next_] = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  glFlush();  // the GPU starts on what is queued while the CPU goes on
  next_ = (next_ + 1) % unsigned(fences_.size());
  ++pending_;
}

const void* Readback::wait() {
  if (pending_ == 0) throw std::logic_error("Readback::wait: nothing pending");
  const unsigned slot = (next_ + unsigned(fences_.size()) - pending_) % unsigned(fences_.size());
  GLsync& fence = fences_[slot];
  while (glClientWaitSync(fence, 0, 1'000'000'000) == GL_TIMEOUT_EXPIRED) {
  }
  glDeleteSync(std::exchange(fence, nullptr));
  --pending_;
  return mapped_ + slot * stride_;
}

}  // namespace hemirad::gl
