// GL errors (docs/errors.md): out of GPU memory names the allocation, --gl-debug reports every
// KHR_debug message and the driver's words for a GL error, and a normal solve raises none.
#include <fcntl.h>
#include <unistd.h>
#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gl/Debug.h"
#include "gl/GL.h"
#include "gl/Objects.h"
#include "tests/bad_input/BadInput.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using namespace hemirad::test::bad_input;
using Catch::Contains;
using hemirad::test::count;
namespace fs = std::filesystem;

namespace {

// Captures what is written to stderr (fd 2) while `fn` runs.
template <class Fn>
std::string captureStderr(Fn&& fn) {
  std::string path = test::tempPath("stderr.txt");
  std::fflush(stderr);
  int saved = dup(2), fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(fd, 2);
  close(fd);
  try {
    fn();
  } catch (...) {
    std::fflush(stderr);
    dup2(saved, 2);
    close(saved);
    throw;
  }
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("GL_OUT_OF_MEMORY allocating a buffer or texture is an error naming the allocation and its size", "[gl]") {
  test::backend();
  CHECK_THROWS_WITH(gl::Buffer(std::size_t(1) << 42),
                    Contains("out of GPU memory allocating a buffer of 4398046511104 bytes (4096.00 GiB)"));
  CHECK_THROWS_WITH(gl::Texture(GL_RGBA32F, 16384, 16384, 2048),
                    Contains("out of GPU memory allocating a 16384 x 16384 x 2048 GL_RGBA32F texture (8192.00 GiB)"));
  CHECK(gl::takeError() == 0);
  CHECK_NOTHROW(gl::Buffer(64));  // and the context goes on working
}

TEST_CASE("With GL debug output every KHR_debug message is reported and a GL error names the driver's message",
          "[gl]") {
  test::backend();
  std::string error;
  std::string printed = captureStderr([&] {
    gl::enableDebugOutput();
    const char* low = "hemirad test: a low-severity message";
    gl::insertDebugMessage(1, false, low);
    gl::insertDebugMessage(2, true, "hemirad test: a notification");
    gl::Buffer().bind(0xdead);  // GL_INVALID_ENUM
    try {
      gl::checkErrors("the test");
    } catch (const gl::Error& e) {
      error = e.what();
    }
    gl::disableDebugOutput();
  });
  INFO(printed);
  CHECK_THAT(printed, Contains("hemirad: GL debug: other (low, id 1): hemirad test: a low-severity message"));
  CHECK_THAT(printed, Contains("hemirad: GL debug: marker (notification, id 2): hemirad test: a notification"));
  CHECK_THAT(printed, Contains("hemirad: GL debug: error (high"));
  CHECK_THAT(error, Contains("GL error 0x0500 (GL_INVALID_ENUM) in the test: "));
  CHECK(error.size() > std::string("GL error 0x0500 (GL_INVALID_ENUM) in the test: ").size());
  CHECK(gl::takeDebugError().empty());
}

TEST_CASE("A solve with --gl-debug runs clean: no GL debug error on the whole path", "[cli][backend]") {
  std::string obj = writeScene("gl-debug", kQuad + "f 1 2 3 4\n");
  std::string out = test::tempPath("gl-debug.png");
  test::Run run = test::hemirad(solve(obj) + " --gl-debug --image " + out);
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK(count(run.output, "hemirad: GL debug: error") == 0);
  CHECK(fs::exists(out));
}
