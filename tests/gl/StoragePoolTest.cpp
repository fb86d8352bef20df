// gl/StoragePool.h: a buffer or texture destroyed waits idle and is handed out again for the same
// shape, reading as fresh storage does; idle storage is capped, oldest out first; and a solve
// built on reused storage gives the bits of one built on fresh storage.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

#include "gl/Objects.h"
#include "gl/StoragePool.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("A buffer handed back is handed out again for its size only, as zeros or the new data", "[gl]") {
  test::backend();
  gl::dropIdleStorage();
  std::vector<std::uint32_t> ones(16, 0xffffffffu), read(16, 7u);
  GLuint first = 0;
  {
    gl::Buffer b{std::span<const std::uint32_t>(ones)};
    first = b.id();
  }
  CHECK(gl::idleStorageBytes() == 64);
  gl::Buffer other(60);  // another size: fresh storage
  CHECK(other.id() != first);
  gl::Buffer again(64);
  CHECK(again.id() == first);
  CHECK(gl::idleStorageBytes() == 0);
  again.read(0, 64, read.data());
  CHECK(read == std::vector<std::uint32_t>(16, 0u));  // what the last owner wrote is gone
  const std::vector<std::uint32_t> data(16, 5u);
  GLuint id = again.id();
  again = gl::Buffer();  // back to the pool
  gl::Buffer withData{std::span<const std::uint32_t>(data)};
  CHECK(withData.id() == id);
  withData.read(0, 64, read.data());
  CHECK(read == data);
}

TEST_CASE("Fresh storage made without data reads as zeros, though a deleted object's memory may back it", "[gl]") {
  // GL leaves fresh storage undefined; a driver may map in what a deleted buffer of this process
  // held (solvers count on zeros: the pool hands storage out again as zeros for that reason).
  test::backend();
  constexpr std::size_t kWords = 1 << 18;  // 1 MiB
  const std::vector<std::uint32_t> pattern(kWords, 0xabababab);
  const std::vector<float> texels(64 * 64 * 4, 3.5f);
  for (int round = 0; round < 4; ++round) {
    {
      gl::Buffer filled{std::span<const std::uint32_t>(pattern)};
      gl::Texture painted(GL_RGBA32F, 64, 64);
      painted.upload(GL_RGBA, GL_FLOAT, texels.data());
    }
    gl::dropIdleStorage();  // deleted: their memory goes back to the driver
    gl::Buffer fresh(kWords * sizeof(std::uint32_t));
    std::vector<std::uint32_t> read(kWords, 1u);
    fresh.read(0, kWords * sizeof(std::uint32_t), read.data());
    CHECK(std::count(read.begin(), read.end(), 0u) == std::ptrdiff_t(kWords));
    gl::Texture texture(GL_RGBA32F, 64, 64);
    std::vector<float> back(texels.size(), 1.0f);
    texture.read(GL_RGBA, GL_FLOAT, back.size() * 4, back.data());
    CHECK(std::count(back.begin(), back.end(), 0.0f) == std::ptrdiff_t(back.size()));
  }
}

TEST_CASE("A texture handed back is handed out again for its format and size, zeroed, with nearest filtering", "[gl]") {
  test::backend();
  gl::dropIdleStorage();
  struct Case {
    GLenum internal, format, type;
  };
  for (const Case c :
       {Case{GL_RGBA32F, GL_RGBA, GL_FLOAT}, Case{GL_R32F, GL_RED, GL_FLOAT}, Case{GL_RGBA8, GL_RGBA, GL_FLOAT},
        Case{GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT}, Case{GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT}}) {
    CAPTURE(c.internal);
    const int channels = c.format == GL_RGBA ? 4 : 1;
    std::vector<float> values(std::size_t(4 * 4 * channels), 0.5f);
    std::vector<std::uint32_t> words(values.size(), 9u);
    GLuint first = 0;
    {
      gl::Texture t(c.internal, 4, 4);
      t.upload(c.format, c.type, c.type == GL_FLOAT ? static_cast<const void*>(values.data()) : words.data());
      t.linearFiltering();
      first = t.id();
    }
    gl::Texture wider(c.internal, 8, 4);
    CHECK(wider.id() != first);
    gl::Texture again(c.internal, 4, 4);
    CHECK(again.id() == first);
    std::vector<float> back(values.size(), 1.0f);
    again.read(c.format, c.type, back.size() * 4, back.data());
    CHECK(std::all_of(back.begin(), back.end(), [](float v) { return v == 0.0f; }));  // (0u reads as 0.0f)
    GLint minFilter = 0;
    glGetTextureParameteriv(again.id(), GL_TEXTURE_MIN_FILTER, &minFilter);
    CHECK(minFilter == GL_NEAREST);
  }
}

TEST_CASE("The storage pool keeps at most 256 idle objects, the most recent", "[gl]") {
  test::backend();
  gl::dropIdleStorage();
  std::size_t kept = 0;  // the sizes of the newest 256 of 300 buffers of 16 (i + 1) bytes
  for (std::size_t i = 0; i < 300; ++i) {
    gl::Buffer b(16 * (i + 1));
    if (i >= 300 - 256) kept += 16 * (i + 1);
  }
  CHECK(gl::idleStorageBytes() == kept);
  CHECK(gl::dropIdleStorage());
  CHECK(gl::idleStorageBytes() == 0);
  CHECK_FALSE(gl::dropIdleStorage());
}

TEST_CASE("A solve on storage another solve handed back gives the bits of one on fresh storage",
          "[gl][heavy]") {  // bits of repeated solves: 7 s under ASan
  const Scene scene = test::cube(0.6, 1.0, 0);
  ProgressiveSettings settings;
  settings.stop = {0, 0.99};
  test::backend();
  gl::dropIdleStorage();
  const test::Solved fresh = test::solve(scene, 0.1, settings);
  REQUIRE(gl::idleStorageBytes() > 0);  // the first solve's storage waits
  const std::size_t idle = gl::idleStorageBytes();
  const test::Solved reused = test::solve(scene, 0.1, settings);
  CHECK(gl::idleStorageBytes() == idle);  // the same shapes again: all of it was taken, then handed back
  CHECK(reused.hash == fresh.hash);
  CHECK(reused.status.shots == fresh.status.shots);
}
