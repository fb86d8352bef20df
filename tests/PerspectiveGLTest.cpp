// Perspective-driven shooting (seed 004 §5): only surfaces in the area of interest receive; the
// stored radiosity table holds the rest and hands it over, exactly, when they come into view.
#include <catch2/catch.hpp>

#include <cmath>

#include "cpu/ExactFormFactor.h"
#include "cpu/Hemisphere.h"
#include "src/scene/SceneLoader.h"
#include "src/walk/Walkthrough.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

// The lamp-lit grey box (test::cube: rho 0.5, lamp ceiling = polygon 1), seen from above the
// floor (polygon 0) with a narrow field of view: only the floor is in view.
const Camera kFloor{{0.5, 0.6, 0.5}, {0.5, 0.0, 0.5}, {0, 0, 1}, 30.0};
constexpr double kRho = 0.5;

ProgressiveSettings perspective(unsigned decayShots) {
  ProgressiveSettings s;
  s.algorithm = Algorithm::Perspective;
  s.shootLevel = 0;  // element by element: sigma is per element
  s.shootersPerPass = 8;
  s.fovDecayShots = decayShots;
  s.viewInterest = 0;      // the simulated field of view alone: the walls are out of the area of interest
  s.itemResolution = 128;  // a convex box: the exact bookkeeping is checked, not the item buffer's resolution
  s.stop = {0, 0.9999};
  return s;
}

// Per face: the power it holds, sum B A, and what every shot so far would have given it had all
// of them reached it, sum rho A_j sum_L F_jL (B_L - dB_L) (B - dB is all element L has shot).
// In a convex box every element sees every other, so the two agree when nothing is held back,
// whatever order the shots came in.
struct FacePower {
  double held[6] = {}, shotAt[6] = {};
};
FacePower facePower(const Scene& s, const Atlas& a, const SolverState& state) {
  const std::vector<glm::vec4> B = state.readRadiosity(), dB = state.readDeltaB();
  FacePower out;
  for (std::size_t j = 0; j < B.size(); ++j) {
    const std::uint32_t face = a.polygonOf[j];
    if (face == kNoPolygon || face == 1) continue;  // the lamp (rho 0) receives nothing
    const glm::dvec3 pj(a.positionArea[j]), nj = s.polygons()[face].normal;
    double gathered = 0;
    for (std::size_t L = 0; L < B.size(); ++L) {
      if (a.polygonOf[L] == kNoPolygon || a.polygonOf[L] == face) continue;
      for (const Poly3& shape : a.elementShape(s, int(L % a.width), int(L / a.width)))
        gathered += cpu::pointToPolygon(pj, nj, shape, s.polygons()[a.polygonOf[L]].normal) * (B[L].x - dB[L].x);
    }
    out.held[face] += B[j].x * a.positionArea[j].w;
    out.shotAt[face] += kRho * gathered * a.positionArea[j].w;
  }
  return out;
}

}  // namespace

TEST_CASE("Out of view nothing is received, and the table hands it all over once the view covers the scene",
          "[heavy][gl][perspective]") {
  test::backend();
  Scene s = test::cube(kRho, 0.0, 1);
  Atlas atlas = buildAtlas(s, 0.1);
  SolverState state(s, atlas);
  ProgressiveSolver solver(state, perspective(400));  // grows at 50, 100, ... 400 shots
  solver.look(kFloor, 1.0);
  REQUIRE(solver.advance(40).shots == 40);
  REQUIRE(solver.perspective()->surfacesInView() == 1);
  FacePower early = facePower(s, atlas, state);
  CHECK(early.held[0] == Approx(early.shotAt[0]).epsilon(1e-4));  // the floor, in view, has all
  for (int face : {2, 3, 4, 5}) {
    INFO("after 40 shots, wall " << face << " holds " << early.held[face] << " of " << early.shotAt[face]);
    CHECK(early.held[face] == 0.0);
    CHECK(early.shotAt[face] > 0.05 * early.shotAt[0]);
  }

  SolveStatus st;
  while (!solver.perspective()->wholeScene() || !solver.perspective()->settled()) st = solver.advance(64);
  CHECK(solver.deliveryShots() > 0);
  FacePower all = facePower(s, atlas, state);
  for (int face : {0, 2, 3, 4, 5}) {
    INFO("after " << st.shots << " shots and " << solver.deliveryShots() << " deliveries, face " << face << " holds "
                  << all.held[face] << " of " << all.shotAt[face]);
    CHECK(all.held[face] == Approx(all.shotAt[face]).epsilon(1e-4));
  }
}

TEST_CASE("A camera move hands the surfaces entering the view their stored entries, a pass in turn with a shot",
          "[heavy][gl][perspective]") {
  // Looking at the floor, then at the wall z = 0 (polygon 2): the wall gets all the shots held
  // for it, and the shots taken meanwhile, exactly once; the floor, out of the camera's view
  // for less than the decay interval, stays in the area of interest; the other walls hold nothing.
  test::backend();
  Scene s = test::cube(kRho, 0.0, 1);
  Atlas atlas = buildAtlas(s, 0.1);
  SolverState state(s, atlas);
  ProgressiveSolver solver(state, perspective(100000));  // no growth: only the camera decides
  solver.look(kFloor, 1.0);
  const SolveStatus st = solver.advance(48);
  CHECK(facePower(s, atlas, state).held[2] == 0.0);
  // The move is applied by the next advance(), whose budget (here one pass, 8 item buffers)
  // goes to a delivery pass; the next pass shoots, and so on while deliveries are due.
  const unsigned deliveries = solver.deliveryShots();
  solver.look({{0.5, 0.5, 0.6}, {0.5, 0.5, 0.0}, {0, 1, 0}, 30.0}, 1.0);
  solver.advance(8);
  CHECK(solver.perspective()->surfacesInView() == 2);
  CHECK(solver.deliveryShots() == deliveries + 8);
  CHECK(solver.advance(0).shots == st.shots);
  CHECK(solver.advance(8).shots == st.shots + 8);  // a shot while deliveries are due
  CHECK(solver.perspective()->delivering());
  while (!solver.perspective()->settled()) solver.advance(8);
  CHECK(solver.deliveryShots() > deliveries + 8);
  FacePower moved = facePower(s, atlas, state);
  INFO("wall 2 holds " << moved.held[2] << " of " << moved.shotAt[2] << "; the floor " << moved.held[0] << " of "
                       << moved.shotAt[0]);
  CHECK(moved.held[2] == Approx(moved.shotAt[2]).epsilon(1e-4));
  CHECK(moved.held[0] == Approx(moved.shotAt[0]).epsilon(1e-4));
  for (int face : {3, 4, 5}) CHECK(moved.held[face] == 0.0);
}
TEST_CASE("Perspective-driven and plain progressive refinement converge to the same solution",
          "[heavy][gl][perspective]") {
  // Per face of the lamp-lit box, to convergence 0.998: only the order of the shots differs.
  test::backend();
  Scene s = test::cube(kRho, 0.0, 1);
  ProgressiveSettings plain;
  plain.shootLevel = 0;
  plain.stop = {0, 0.998};
  ProgressiveSettings driven = perspective(200);
  driven.shootersPerPass = 16;
  driven.stop = {0, 0.998};
  for (ProgressiveSettings* p : {&plain, &driven})  // nothing occludes inside a cube: the smallest exact item buffer
    p->projection = Projection::Hemicube, p->itemSubdivision = 0, p->itemResolution = 64;
  test::Solved a = test::solve(s, 0.125, plain), b = test::solve(s, 0.125, driven, &kFloor);
  for (std::uint32_t face = 0; face < 6; ++face) {
    double ma = 0, mb = 0, area = 0;
    for (std::size_t t = 0; t < a.B.size(); ++t)
      if (a.atlas.polygonOf[t] == face) {
        ma += a.B[t].x * a.atlas.positionArea[t].w;
        mb += b.B[t].x * b.atlas.positionArea[t].w;
        area += a.atlas.positionArea[t].w;
      }
    INFO("face " << face << ": progressive " << ma / area << " (" << a.status.shots << " shots), perspective "
                 << mb / area << " (" << b.status.shots << ")");
    CHECK(mb / area == Approx(ma / area).epsilon(0.002));
  }
}

TEST_CASE(
    "Along a walk through the doors of four rooms, perspective-driven shooting shoots every frame, deliveries "
    "taking at most every other pass",
    "[gl][perspective][walkthrough]") {
  // Issue 19: a camera that moves every frame brings surfaces into view every frame. Were their
  // entries delivered before any further shot, the frame budget would go to deliveries and the
  // view would stop brightening (main before the fix: no shot from 1.5 s to 10.5 s of the
  // 16-room walk). Importance-driven shooting walks alongside for the record (INFO).
  test::backend();
  const Scene s = loadScene(test::sourcePath("scenes/building/building_4.obj"));
  const CameraPath path =
      readCameraPath(test::sourcePath("scenes/building/building_4.path"), resolveCamera(s, std::nullopt));
  const Atlas atlas = buildAtlas(s, texelSizeForElements(s, 600), 4096);
  ProgressiveSettings settings;
  settings.shootersPerPass = 8, settings.itemSubdivision = 1, settings.itemResolution = 64;
  ConvergedViews converged(s, atlas, settings, 0.95, false);
  WalkthroughOptions w;
  w.fps = 0.5, w.frameShots = 16, w.width = w.height = 32, w.ambient = false;
  std::vector<FrameRecord> frames[2];
  for (int k = 0; k < 2; ++k) {
    SolverState state(s, atlas);
    settings.algorithm = k ? Algorithm::Perspective : Algorithm::Importance;
    settings.stop = {0, 0.99999};
    ProgressiveSolver solver(state, settings);
    frames[k] = walk(solver, state, path, converged, w);
  }
  REQUIRE(frames[1].size() == 7);
  for (std::size_t f = 1; f < frames[1].size(); ++f) {
    const FrameRecord &importance = frames[0][f], &perspective = frames[1][f], &before = frames[1][f - 1];
    INFO("frame " << f << ": importance " << importance.imageError << " after " << importance.shots
                  << " shots; perspective " << perspective.imageError << " after " << perspective.shots << " shots and "
                  << perspective.deliveryShots << " deliveries");
    CHECK(perspective.shots >= before.shots + 8);               // at least one shooting pass of the frame's two
    CHECK(perspective.deliveryShots <= perspective.shots + 8);  // a delivery pass (<= 8) per shooting pass, + 1
  }
}
