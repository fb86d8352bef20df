#include <catch2/catch.hpp>
#include <cstring>

#include "cpu/Hemisphere.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {
Scene furnace(double rho, double E) { return test::cube(rho, E); }

// 1 - sum luminance(dB) A / sum luminance(E) A, from a readback.
double convergenceOf(const Scene& s, const test::Solved& r) {
  double unshot = 0, emitted = 0;
  for (size_t t = 0; t < r.dB.size(); ++t) {
    if (r.atlas.polygonOf[t] == kNoPolygon) continue;
    double A = r.atlas.positionArea[t].w;
    unshot += luminance(glm::dvec3(r.dB[t])) * A;
    emitted += luminance(s.materials[s.polygons()[r.atlas.polygonOf[t]].material].emission) * A;
  }
  return 1 - unshot / emitted;
}
}  // namespace

TEST_CASE("Test furnace faces all point into the box", "[cpu]") {
  Scene s = furnace(0.5, 1.0);
  for (const auto& p : s.polygons()) {
    glm::dvec3 c(0.0);
    for (auto& v : p.vertices) c += v / double(p.vertices.size());
    CHECK(glm::dot(glm::dvec3(0.5) - c, p.normal) > 0);
  }
}

TEST_CASE("A closed box of emitting grey walls converges to B = E / (1 - rho) within 0.1%", "[heavy][gl]") {
  // Exact form factors hand on everything a shooter emits in a closed box (row sum 1), so every
  // wall settles at E / (1 - rho); the disc approximation (docs/design.md#form-factor) lost 2.3% here (rho 0.5:
  // 1.953 for 2). Batched passes (16 shooters from one unshot state), shooting blocks and the
  // bench's planned shooting (coarse blocks, planned item buffer, either projection) must reach the same answer.
  for (auto [rho, shooters, level, projection] : {std::tuple{0.5, 16, 0, Projection::Hemicube},
                                                  {0.5, 1, 2, Projection::Hemicube},
                                                  {0.5, 16, kAutoShootLevel, Projection::Orthographic},
                                                  {0.5, 16, kAutoShootLevel, Projection::Hemicube}}) {
    Scene s = furnace(rho, 1.0);
    ProgressiveSettings settings;  // the hemicube rows: the default (the fast preset)
    if (projection == Projection::Orthographic) settings.usePreset("seed003");  // L3, 512^2
    settings.shootLevel = level;
    if (level == kAutoShootLevel) settings.itemResolution = kAutoItemResolution;
    settings.shootersPerPass = shooters;
    settings.stop.targetConvergence = 0.9995;  // what is left unshot lowers B by < 0.05%
    test::Solved r = test::solve(s, 1.0 / 8, settings);
    double mean = test::object(r, "box").mean.x, exact = 1 / (1 - rho);
    INFO("rho " << rho << ", " << shooters << " shooters a pass, level " << level << ", " << projectionName(projection)
                << ": mean B " << mean << " after " << r.status.shots << " shots; E/(1-rho) " << exact);
    CHECK(mean == Approx(exact).epsilon(0.001));
  }
}

TEST_CASE("Energy is conserved: in a closed box every shot delivers what its form factors hand on", "[gl]") {
  // A black lamp (rho 0, E 1, 100 elements) on the ceiling of a grey box. Lamp elements have the
  // largest unshot power, so the first 100 shots are exactly the lamp's. Walls hold
  // B = rho * irradiance, so sum B A / rho is the power received; it must equal what the shots
  // handed on, sum_s sigma_s E A_s (sigma_s the exact row sum of what the gather computes), and
  // the power shot (1) to within the centroid rule's error (measured 0.1%).
  // Passes of 20 shooters hand on the same: the lamp's 100 elements in 5 passes.
  const double rho = 0.5;
  const int shooters = GENERATE(1, 20);
  INFO(shooters << " shooters a pass");
  Scene s = test::cube(rho, 0.0, 1);
  ProgressiveSettings settings;
  settings.shootLevel = 0;  // element by element
  settings.shootersPerPass = shooters;
  settings.stop.maxShots = 100;
  test::Solved r = test::solve(s, 0.1, settings);
  REQUIRE(r.status.shots == 100);
  double received = 0, handedOn = 0, shot = 0;
  for (size_t t = 0; t < r.B.size(); ++t) {
    if (r.atlas.polygonOf[t] == kNoPolygon) continue;
    double A = r.atlas.positionArea[t].w;
    if (r.atlas.polygonOf[t] == 1) {
      CHECK(r.dB[t].x == 0.0f);
      shot += A;
      handedOn += test::exactRowSum(s, r.atlas, t) * A;
    } else {
      received += r.B[t].x * A / rho;
    }
  }
  INFO("shot " << shot << ", handed on " << handedOn << ", received " << received);
  CHECK(received == Approx(handedOn).epsilon(0.002));
  CHECK(received == Approx(shot).epsilon(0.003));
  // Convergence is what is no longer unshot: all that was shot, less rho * received now unshot.
  CHECK(r.status.convergence == Approx(shot - rho * received).margin(1e-4));
  CHECK(r.status.convergence == Approx(convergenceOf(s, r)).margin(1e-5));
}

TEST_CASE("Two solves of the same scene are bitwise identical, one shooter a pass or 16", "[heavy][gl]") {
  ProgressiveSettings settings;
  settings.shootLevel = 0;  // element by element
  settings.shootersPerPass = GENERATE(1, 16);
  settings.stop.targetConvergence = 0.8;
  Scene s = loadScene(test::sourcePath("scenes/analytic/parallel_squares.obj"));
  test::Solved a = test::solve(s, 0.05, settings), b = test::solve(s, 0.05, settings);
  CHECK(a.status.shots == b.status.shots);
  CHECK(a.hash == b.hash);
  CHECK(std::memcmp(a.B.data(), b.B.data(), a.B.size() * sizeof(glm::vec4)) == 0);
}

TEST_CASE("The shooters are the blocks with the largest unshot power, and --shots stops exactly", "[gl]") {
  // Two lamps over a floor: the bright one (E 3) shoots all 25 of its elements before the dim
  // one, one a pass or 8 (8 + 8 + 8 + 1: the last pass is cut to the shot budget).
  Scene s;
  int o = s.addObject("scene");
  s.addPolygon(test::rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 1), test::material(s, 0.5, 0.0), o);
  s.addPolygon(test::rectangle({0, 1, 0}, {1, 0, 0}, {0, 0, 1}, 0.5, 0.5), test::material(s, 0.0, 1.0), o);
  s.addPolygon(test::rectangle({0.5, 1, 0.5}, {1, 0, 0}, {0, 0, 1}, 0.5, 0.5), test::material(s, 0.0, 3.0), o);
  ProgressiveSettings settings;
  settings.shootLevel = 0;  // element by element
  settings.shootersPerPass = GENERATE(1, 8);
  settings.stop.maxShots = 25;
  test::Solved r = test::solve(s, 0.1, settings);
  CHECK(r.status.shots == 25);
  int dimUnshot = 0, brightShot = 0;
  for (size_t t = 0; t < r.dB.size(); ++t) {
    dimUnshot += r.atlas.polygonOf[t] == 1 && r.dB[t].x == 1.0f;
    brightShot += r.atlas.polygonOf[t] == 2 && r.dB[t].x == 0.0f;
  }
  CHECK(dimUnshot == 25);
  CHECK(brightShot == 25);
  CHECK(r.status.convergence == Approx(convergenceOf(s, r)).margin(1e-5));
}

TEST_CASE("Substructured shooting converges to the per-texel solution", "[gl]") {
  Scene s = loadScene(test::sourcePath("scenes/analytic/parallel_squares.obj"));
  ProgressiveSettings fine, coarse;
  fine.shootLevel = 0;
  fine.stop.targetConvergence = coarse.stop.targetConvergence = 0.99;
  coarse.shootLevel = 2;
  test::Solved a = test::solve(s, 1.0 / 16, fine), b = test::solve(s, 1.0 / 16, coarse);
  CHECK(b.status.shots < a.status.shots / 8);
  double ra = test::object(a, "receiver").mean.x, rb = test::object(b, "receiver").mean.x;
  INFO("per-texel " << ra << " (" << a.status.shots << " shots), 4x4 blocks " << rb << " (" << b.status.shots << ")");
  CHECK(rb == Approx(ra).epsilon(0.02));
}

TEST_CASE("Scenes with many shooter blocks reduce in parallel levels and pick the same shooters", "[heavy][gl]") {
  // 6,480 blocks at shoot level 0 (over the 1,024 that select.comp ranks alone): a lamp of 400
  // elements at E 3 over a floor of 6,080 must still shoot every lamp element first, also 16 a
  // pass, where each level's groups must hand on their best 16, not their best one.
  Scene s;
  int o = s.addObject("scene");
  s.addPolygon(test::rectangle({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 1, 0.95), test::material(s, 0.5, 0.0), o);
  s.addPolygon(test::rectangle({0, 1, 0}, {1, 0, 0}, {0, 0, 1}, 0.25, 0.25), test::material(s, 0.0, 3.0), o);
  ProgressiveSettings settings;
  settings.shootLevel = 0;
  settings.itemSubdivision = 1;
  settings.shootersPerPass = GENERATE(1, 16);
  settings.stop.maxShots = 400;
  test::Solved r = test::solve(s, 0.0125, settings);
  REQUIRE(r.atlas.elements == 6480);
  int lampShot = 0;
  for (size_t t = 0; t < r.dB.size(); ++t) lampShot += r.atlas.polygonOf[t] == 1 && r.dB[t].x == 0.0f;
  CHECK(lampShot == 400);
  CHECK(r.status.convergence == Approx(convergenceOf(s, r)).margin(1e-5));
}

TEST_CASE("Batched passes converge to the one-shooter solution", "[gl]") {
  // Shooting 16 blocks from one unshot state changes the order of the shots, not the answer.
  Scene s = loadScene(test::sourcePath("scenes/analytic/perpendicular_squares.obj"));
  ProgressiveSettings one, batched;
  one.shootLevel = batched.shootLevel = 0;
  one.stop.targetConvergence = batched.stop.targetConvergence = 0.995;
  batched.shootersPerPass = 16;
  test::Solved a = test::solve(s, 1.0 / 16, one), b = test::solve(s, 1.0 / 16, batched);
  for (const char* name : {"emitter", "receiver"}) {
    double ra = test::object(a, name).mean.x, rb = test::object(b, name).mean.x;
    INFO(name << ": one a pass " << ra << " (" << a.status.shots << " shots), 16 a pass " << rb << " ("
              << b.status.shots << ")");
    CHECK(rb == Approx(ra).epsilon(0.005));
  }
  CHECK(b.status.shots <= a.status.shots + 16 * 4);
}

TEST_CASE("Running ahead of the status readback gives advance()'s radiosity bits and final status",
          "[gl][heavy]") {  // bits of repeated solves: 8 s under ASan
  // advanceAhead() returns the status a batch late; the passes enqueued after the stop rule fired
  // are empty, so settle() ends where advance() does, whatever the batch sizes.
  Scene s = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  ProgressiveSettings settings;
  settings.stop = GENERATE(StopRule{0, 0.95}, StopRule{200, 0});
  const test::Solved synced = test::solve(s, 20.0, settings);
  SolverState state(s, synced.atlas);
  ProgressiveSolver solver(state, settings);
  SolveStatus status;
  unsigned batches = 0;
  for (unsigned batch = 1; !status.done; batch = batch % 5 + 1, ++batches) status = solver.advanceAhead(batch * 16);
  const SolveStatus settled = solver.settle(status);
  INFO("synced: " << synced.status.shots << " shots, ahead: " << settled.shots << " in " << batches << " batches");
  CHECK(batches > 2);
  CHECK(settled.done);
  CHECK(settled.shots == synced.status.shots);
  CHECK(settled.convergence == synced.status.convergence);
  CHECK(radiosityHash(synced.atlas, state.readRadiosity()) == synced.hash);
}
