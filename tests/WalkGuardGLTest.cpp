// llvmpipe (Mesa 22.3) counts a shader invocation's loop turns with one counter for all its loops
// and, past 65,535 (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS), ends every loop at its next turn: a
// BVH walk cut there answers wrongly and silently. The walks flag it (shaders/bvh.glsl) and the
// host refuses the answer (BvhBuffers::requireWholeWalks) or draws again in shares (Renderer).
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "gl/Backend.h"
#include "gl/State.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/BvhBuffers.h"
#include "src/solver/ShaderContract.h"
#include "src/solver/SolverState.h"
#include "tests/support/Support.h"

using namespace hemirad;

TEST_CASE("Where llvmpipe's loop limit cuts a BVH walk short, the walk says so and the host refuses its answer",
          "[gl]") {
  test::backend();
  const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, 300));
  SolverState state(scene, atlas);
  const BvhBuffers bvh{Bvh(scene)};
  gl::Program program = computeProgram("walk_guard_probe.comp");
  gl::Buffer out{sizeof(std::uint32_t[2])};
  // Across the room at mid height, through the tall block (x 265-472 at z 350): blocked.
  program.set("from", 100.0f, 100.0f, 350.0f);
  program.set("to", 520.0f, 100.0f, 350.0f);
  auto probe = [&](unsigned turns) {
    state.bindScene();
    bvh.bind();
    out.bindBase(GL_SHADER_STORAGE_BUFFER, slot::SSBO_PROBE_OUT);
    program.set("turns", turns);
    program.use();
    gl::Program::dispatch(1);
    gl::barrier(gl::Barrier::BufferUpdate);
    std::vector<std::uint32_t> r(2);
    out.read(0, sizeof(std::uint32_t[2]), r.data());
    return r;
  };
  const std::vector<std::uint32_t> few = probe(1000);
  CHECK(few[0] == 1000);
  CHECK(few[1] == 1);  // the tall block is in the way
  CHECK_FALSE(bvh.walksCut());
  CHECK_NOTHROW(bvh.requireWholeWalks("probe"));
  const std::vector<std::uint32_t> many = probe(100000);
  if (gl::softwareRenderer()) {
    CHECK(many[0] == 65535);  // every loop of the invocation, together
    CHECK(many[1] == 0);      // the walk after it took one turn and answered wrongly: not blocked
    CHECK(bvh.walksCut());    // but said so
    CHECK_THROWS_WITH(bvh.requireWholeWalks("probe"), Catch::Contains("ended a BVH walk early"));
    bvh.clearWalksCut();
    CHECK_FALSE(bvh.walksCut());
  } else {  // a GPU driver ends no loop early
    CHECK(many[0] == 100000);
    CHECK(many[1] == 1);
    CHECK_FALSE(bvh.walksCut());
  }
}
