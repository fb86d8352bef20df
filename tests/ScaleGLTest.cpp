// Issue 29, scale without limits: a scene's size is bounded by memory, never by a GL dispatch
// limit. More than 65,535 polygons (each at least one shooter block) overflowed one dimension of
// GL_MAX_COMPUTE_WORK_GROUP_COUNT, the least a GL 4.5 driver must give.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "gl/Limits.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/SolverState.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

constexpr int kRows = 250, kColumns = 280;  // 70,000 wall triangles

// A lamp over a floor, and beside them a wall of kRows x kColumns tiny triangles facing +x:
// every triangle is a polygon of its own, so one shooter block at least. Returns the OBJ's path.
std::string manyTriangleScene() {
  const std::string dir = test::tempPath("many-triangles");
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/m.mtl") << "newmtl lamp\nKd 0 0 0\nKe 1 1 1\nnewmtl grey\nKd 0.5 0.5 0.5\n";
  std::ofstream obj(dir + "/s.obj");
  obj << "mtllib m.mtl\n"
         "o floor\nusemtl grey\nv 0 0 0\nv 0 0 1\nv 1 0 1\nv 1 0 0\nf 1 2 3 4\n"
         "o lamp\nusemtl lamp\nv 0.4 1 0.4\nv 0.6 1 0.4\nv 0.6 1 0.6\nv 0.4 1 0.6\nf 5 6 7 8\n"
         "o wall\nusemtl grey\n";
  const double cell = 0.9 / kColumns, side = cell / 2;
  int v = 9;
  for (int r = 0; r < kRows; ++r)
    for (int c = 0; c < kColumns; ++c, v += 3) {
      const double y = 0.05 + r * cell, z = 0.05 + c * cell;
      obj << fmt::format("v 0 {0} {1}\nv 0 {2} {1}\nv 0 {0} {3}\nf {4} {5} {6}\n", y, z, y + side, z + side, v, v + 1,
                         v + 2);
    }
  return dir + "/s.obj";
}

// Caps the grid's dimensions for a test's span (small scenes then tile), whatever it throws.
struct CappedGrid {
  explicit CappedGrid(unsigned perDimension) { gl::limitWorkGroupCount(perDimension); }
  ~CappedGrid() { gl::limitWorkGroupCount(0); }
};

}  // namespace

TEST_CASE("A 1D workgroup count tiles into a grid within the per-dimension limit with fewer than a row to spare",
          "[gl][scale]") {
  test::backend();
  CappedGrid cap(100);
  for (std::uint64_t groups : {1u, 99u, 100u, 101u, 9999u, 10000u, 10001u, 123457u, 999999u, 1000000u}) {
    const gl::Grid g = gl::tiledGrid(groups);
    INFO(groups << " groups: " << g.x << " x " << g.y << " x " << g.z);
    CHECK(std::max({g.x, g.y, g.z}) <= 100u);
    const std::uint64_t cells = std::uint64_t(g.x) * g.y * g.z;
    CHECK(cells >= groups);
    CHECK(cells - groups < std::uint64_t(g.y + 1) * g.z);  // per layer, less than a column idle
  }
  CHECK(gl::tiledGrid(101).y == 2);
  CHECK(gl::tiledGrid(10001).z == 2);
  CHECK_THROWS_WITH(gl::tiledGrid(1000001), Catch::Contains("GL_MAX_COMPUTE_WORK_GROUP_COUNT"));
}

TEST_CASE("A storage block over GL_MAX_SHADER_STORAGE_BLOCK_SIZE is one error naming what needs it and the limit",
          "[gl][scale]") {
  test::backend();
  const std::size_t most = gl::limits().storageBlockBytes;
  REQUIRE(most >= std::size_t(1) << 27);  // GL 4.5's least
  CHECK_NOTHROW(gl::requireStorageBlock(most, "the shapes of 3 shooter-tree nodes"));
  CHECK_THROWS_WITH(gl::requireStorageBlock(most + 1, "the shapes of 3 shooter-tree nodes"),
                    Catch::Contains("the shapes of 3 shooter-tree nodes needs") &&
                        Catch::Contains("over the GPU's GL_MAX_SHADER_STORAGE_BLOCK_SIZE of"));
}

TEST_CASE("A solve whose dispatches tile over a 3D grid gives the radiosity of one-row dispatches bit for bit",
          "[gl][scale]") {
  const Scene scene = test::cube(0.5, 0.0, 1);
  ProgressiveSettings settings;
  settings.shootLevel = 0;  // 2,400 one-element blocks: 16 x 15 x 10 node_stats groups when capped at 16
  settings.shootersPerPass = 4;
  settings.itemResolution = 64;
  settings.stop = {24, 0};
  const test::Solved plain = test::solve(scene, 0.05, settings);
  REQUIRE(plain.atlas.elements == 2400);
  test::Solved tiled;
  {
    CappedGrid cap(16);
    CHECK(gl::tiledGrid(2400).z == 10);
    tiled = test::solve(scene, 0.05, settings);
  }
  CHECK(tiled.status.shots == 24);
  CHECK(tiled.status.convergence == plain.status.convergence);
  CHECK(tiled.hash == plain.hash);
}

TEST_CASE(
    "A scene of 70,000 polygons, more shooter blocks than one dispatch dimension holds, solves with its light "
    "reaching the floor",
    "[heavy][gl][scale]") {  // ~5 s optimized; the capped-grid test above runs the same paths under ASan
  test::backend();
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = loadScene(manyTriangleScene());
  REQUIRE(scene.polygons().size() == 2 + kRows * kColumns);
  const Atlas atlas = buildAtlas(scene, 0.05, 16384, 0, kPolygonCharts);  // unclustered (Clusters.h): a block each
  SolverState state(scene, atlas);
  ProgressiveSettings settings;
  settings.itemSubdivision = 0;  // 70,000 item-mesh triangles, not 64 times as many: seconds on llvmpipe
  settings.shootersPerPass = 4;
  settings.itemResolution = 128;
  settings.stop = {8, 0};
  ProgressiveSolver solver(state, settings);
  CHECK(solver.shooterBlocks() > 65535);
  SolveStatus status;
  REQUIRE_NOTHROW(status = solver.advance(8));  // the GL error (GL_INVALID_VALUE) surfaced here
  CHECK(status.shots == 8);
  // The lamp shot first: part of its power is unshot again on the floor and wall, less than all of it.
  CHECK(status.convergence > 0.0f);
  CHECK(status.convergence < 1.0f);
  const std::vector<ObjectRadiosity> objects = objectRadiosity(scene, atlas, state.readRadiosity());
  CHECK(objects[0].name == "floor");
  CHECK(objects[0].mean.y > 0.0);
  WARN("seconds: " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}
