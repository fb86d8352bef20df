// gl/ProgramPool.h: a program destroyed waits idle and is handed out again for the same sources,
// to one owner at a time, with its uniforms as a fresh link gives them.
#include <catch2/catch.hpp>

#include "gl/ProgramPool.h"
#include "src/solver/ShaderContract.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
float uniformOf(const gl::Program& p, const char* name) {
  float v = -1.0f;
  glGetUniformfv(p.id(), p.location(name), &v);
  return v;
}
GLint unitOf(const gl::Program& p, const char* name) {
  GLint v = -1;
  glGetUniformiv(p.id(), p.location(name), &v);
  return v;
}
}  // namespace

TEST_CASE("A program handed back is handed out again for the same sources, its uniforms as linked", "[gl]") {
  test::backend();
  GLuint first = 0, second = 0;
  GLint unit = -1;
  {
    gl::Program p = computeProgram("gradient.comp");
    first = p.id();
    unit = unitOf(p, "radiosity");  // layout(binding = IMAGE_RADIOSITY): set at link
    CHECK(uniformOf(p, "threshold") == 0.0f);
    p.set("threshold", 0.25f);
    gl::Program other = computeProgram("gradient.comp");  // the first is owned: a program of its own
    CHECK(other.id() != first);
    other.set("threshold", 0.5f);
    second = other.id();
    gl::Program different = computeProgram("gradient.comp", {{"UNUSED_DEFINE", "1"}});
    CHECK(different.id() != first);
  }
  CHECK(gl::idlePrograms() >= 3);
  gl::Program again = computeProgram("gradient.comp");
  CHECK(glIsProgram(again.id()) == GL_TRUE);
  const bool reused = again.id() == first || again.id() == second;  // one of the two idle ones
  CHECK(reused);
  CHECK(uniformOf(again, "threshold") == 0.0f);  // what the last owner set is gone
  CHECK(unitOf(again, "radiosity") == unit);     // what the link set stays
}

TEST_CASE("The program pool keeps at most 64 idle programs, the most recent", "[gl]") {
  test::backend();
  GLuint latest = 0;
  for (int i = 0; i < 70; ++i) {
    gl::Program p = computeProgram("gradient.comp", {{"POOL_TEST_VARIANT", std::to_string(i)}});
    latest = p.id();
  }
  CHECK(gl::idlePrograms() == 64);
  gl::Program again = computeProgram("gradient.comp", {{"POOL_TEST_VARIANT", "69"}});
  CHECK(again.id() == latest);  // the most recent was kept
  CHECK(gl::idlePrograms() == 63);
}
