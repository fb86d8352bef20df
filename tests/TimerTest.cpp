#include <catch2/catch.hpp>
#include <chrono>

#include "gl/Timer.h"
#include "src/scene/Atlas.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ProgressiveSolver.h"
#include "tests/support/Support.h"

using namespace hemirad;
using hemirad::gl::GpuTimer;
using hemirad::gl::TimerMode;

// Which passes a solver stamps (the bench's split needs them all on a hardware GPU; a solve's own
// timings stamp a sample, whose totals are scaled; untimed runs pay for none).
TEST_CASE("GPU timing stamps one pass in 16 by default, every pass for the bench's split, and none when off",
          "[timer]") {
  unsigned sampled = 0, every = 0, synchronous = 0, off = 0;
  for (unsigned pass = 0; pass < 64; ++pass) {
    sampled += GpuTimer(TimerMode::Gpu).due(pass);
    every += GpuTimer(TimerMode::GpuEveryPass).due(pass);
    synchronous += GpuTimer(TimerMode::Synchronous).due(pass);
    off += GpuTimer(TimerMode::Off).due(pass);
  }
  CHECK(sampled == 64 / GpuTimer::kStride);
  CHECK(GpuTimer(TimerMode::Gpu).due(0));
  CHECK(every == 64);
  CHECK(synchronous == 64);
  CHECK(off == 0);
}

// A solve running ahead reads its status while the next chunk's stamps are still queued: the
// timer then reads only what the GPU has stamped and keeps an interval whose end is not stamped.
TEST_CASE("Collecting without waiting keeps an interval whose end is not yet stamped, and reads it later",
          "[gl][timer]") {
  gl::RenderBackend& backend = test::backend();
  GpuTimer timer(TimerMode::GpuEveryPass);  // stamps even on a CPU rasterizer: the queries are tested
  double totals[2] = {0, 0};
  timer.mark(0);
  backend.finish();
  timer.collect(totals, false);  // one stamp, no interval yet
  CHECK(totals[0] == 0.0);
  timer.mark(1);
  timer.stop();
  backend.finish();
  timer.collect(totals, false);  // every stamp is there now: both intervals
  const double first = totals[0], second = totals[1];
  CHECK(first > 0.0);
  CHECK(second > 0.0);
  timer.collect(totals, true);  // nothing left to add
  CHECK(totals[0] == first);
  CHECK(totals[1] == second);
}

// A solve's timings (the report's timings_ms) on llvmpipe, whose GL_TIMESTAMPs stamp work when it
// is queued: sampled stamps there charged the timed passes with what was queued before them
// (Cornell box 10k: 748 ms of stages in a 444 ms solve; real_20k: select 4,228 ms, gather 4 ms),
// so a software context times every stage by waiting for it. Its stages are then parts of the
// solve: together no more than the solve's wall time, and most of it.
TEST_CASE("On a CPU rasterizer a solve's stage timings are parts of its wall time", "[gl][timer]") {
  gl::RenderBackend& backend = test::backend();
  if (!backend.software()) return;  // a hardware GPU's stamps are where the work ran
  Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Atlas atlas = buildAtlas(scene, texelSizeForElements(scene, 2000));
  SolverState state(scene, atlas);
  ProgressiveSettings settings;  // the default: GPU stamps
  settings.stop.targetConvergence = 0.9;
  ProgressiveSolver solver(state, settings);
  backend.finish();
  const auto t0 = std::chrono::steady_clock::now();
  const SolveStatus status = advanceToStop(solver, {});
  backend.finish();
  const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  const PassTimings& t = solver.timings();
  const double stages = t.select + t.itemBuffer + t.gather;
  INFO(status.shots << " shots in " << wall << " ms; select " << t.select << ", item buffer " << t.itemBuffer
                    << ", gather " << t.gather << " ms");
  CHECK(stages <= wall);
  CHECK(stages > 0.5 * wall);
}
