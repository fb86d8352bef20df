// gl::Readback (gl/Readback.h): copies come back in the order they were enqueued, each with the
// bytes its buffer held when its copy was enqueued, however the buffer changed after.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "gl/Readback.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
std::uint32_t word(const void* bytes) {
  std::uint32_t w = 0;
  std::memcpy(&w, bytes, sizeof w);
  return w;
}
}  // namespace

TEST_CASE("A readback hands back each copy in order, with the bytes the buffer held when it was enqueued", "[gl]") {
  test::backend();
  gl::Buffer source(16);
  gl::Readback readback(sizeof(std::uint32_t), 2);
  const std::uint32_t first = 0x11223344u, second = 0xdeadbeefu;
  source.clear(first);
  readback.copy(source);
  source.clear(second);  // after the first copy: it must not see this
  readback.copy(source);
  CHECK(readback.pending() == 2);
  CHECK_THROWS_AS(readback.copy(source), std::logic_error);  // both slots are pending
  CHECK(word(readback.wait()) == first);
  CHECK(word(readback.wait()) == second);
  CHECK(readback.pending() == 0);
  CHECK_THROWS_AS(readback.wait(), std::logic_error);
  source.clear(first);
  readback.copy(source);  // the ring wraps to its first slot
  CHECK(word(readback.wait()) == first);
}
