// GL handles (gl/Objects.h) own their names: a move hands the name over and empties the source,
// a move-assignment releases what the target held, and destruction releases the name, once.
// Released storage waits in the pool (gl/StoragePool.h): its idle bytes count the releases.
#include <catch2/catch.hpp>
#include <utility>

#include "gl/Objects.h"
#include "gl/StoragePool.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("A GL handle moves its name and releases it exactly once", "[gl]") {
  test::backend();
  gl::dropIdleStorage();
  GLuint first = 0, second = 0;
  {
    gl::Buffer a(64);
    first = a.id();
    REQUIRE(gl::isBuffer(first));
    gl::Buffer b(std::move(a));
    CHECK(a.id() == 0);  // NOLINT(bugprone-use-after-move): the moved-from state is the contract
    CHECK_FALSE(bool(a));
    CHECK(b.id() == first);
    gl::Buffer c(16);
    second = c.id();
    c = std::move(b);  // c's own buffer is released, b's taken
    CHECK(gl::idleStorageBytes() == 16);
    CHECK(c.id() == first);
    CHECK(gl::isBuffer(first));
    c = std::move(c);  // self-move keeps the name
    CHECK(gl::isBuffer(first));
  }
  CHECK(gl::idleStorageBytes() == 16 + 64);  // released with the last owner; the moved-from ones released nothing
  GLuint texture = 0;
  {
    gl::Texture t(GL_RGBA32F, 4, 4);
    texture = t.id();
    CHECK(gl::isTexture(texture));
    gl::Texture moved = std::move(t);
    CHECK(gl::isTexture(texture));
  }
  CHECK(gl::idleStorageBytes() == 16 + 64 + 4 * 4 * 16);
  gl::dropIdleStorage();  // the names go back to the driver
  CHECK_FALSE(gl::isBuffer(first));
  CHECK_FALSE(gl::isBuffer(second));
  CHECK_FALSE(gl::isTexture(texture));
}
