#include "src/walk/Walkthrough.h"

#include <fmt/format.h>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Progress.h"
#include "src/output/ShownRadiosity.h"

namespace hemirad {

ConvergedViews::ConvergedViews(const Scene& scene, const Atlas& atlas, ProgressiveSettings settings, double convergence,
                               bool progress)
    : state_(scene, atlas), renderer_(state_) {
  settings.algorithm = Algorithm::Progressive;
  settings.stop = {0, convergence};
  ProgressiveSolver solver(state_, settings);
  if (progress) fmt::print(stderr, "hemirad: the reference solve, to convergence {}\n", convergence);
  Progress bar(settings.stop, progress);
  const SolveStatus status = advanceToStop(solver, {}, [&](const SolveStatus& s) { bar.update(s); });
  bar.finish();
  shots_ = status.shots;
  renderer_.show(shownRadiosity(scene, atlas, state_.readRadiosity()));  // frames compare shown with shown
}

namespace {
// "frame k of n" on stderr, at most every few seconds: a walkthrough of minutes is not silent.
class FrameProgress {
 public:
  FrameProgress(int frames, bool enabled) : frames_(frames), enabled_(enabled) {}
  void frameDone(int frame) {
    const auto now = std::chrono::steady_clock::now();
    if (!enabled_ || (now - last_ < std::chrono::seconds(3) && frame + 1 < frames_)) return;
    last_ = now;
    fmt::print(stderr, "hemirad: frame {} of {}\n", frame + 1, frames_);
  }

 private:
  int frames_;
  bool enabled_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};
}  // namespace

std::vector<FrameRecord> walk(ProgressiveSolver& solver, SolverState& state, const CameraPath& path,
                              ConvergedViews& converged, const WalkthroughOptions& o) {
  using Clock = std::chrono::steady_clock;
  if (!o.framesDir.empty() && !o.writeFrame) throw std::logic_error("walk: a frames folder without a frame writer");
  if (!o.framesDir.empty()) std::filesystem::create_directories(o.framesDir);
  Renderer renderer(state);
  renderer.stitchLive();  // frames show seams stitched, as solve's images do
  const double aspect = double(o.width) / o.height;
  const int frames = int(std::floor(path.duration() * o.fps + 1e-9)) + 1;
  std::vector<FrameRecord> records;
  FrameProgress progress(frames, o.progress);
  double solveMs = 0, scale = 0;
  SolveStatus status = solver.advance(0);
  Camera last;
  for (int f = 0; f < frames; ++f) {
    FrameRecord r;
    r.frame = f;
    r.time = f / o.fps;
    const Camera camera = path.at(r.time);
    const auto t0 = Clock::now();
    auto elapsedMs = [&] { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); };
    const bool moved = f == 0 || camera != last;
    if (solver.viewDriven() && moved) {
      solver.look(camera, aspect);
      status = solver.advance(0);  // a perspective-driven solve has entries to deliver again
    }
    last = camera;
    if (o.frameShots) {
      if (!status.done) status = solver.advance(o.frameShots);
    } else {
      unsigned batch = 1;
      status = advanceWhile(solver, status, batch, [&] { return elapsedMs() < o.frameMs; });
    }
    solveMs += elapsedMs();

    renderer.setAmbient(false);
    const Image plain = renderer.render(camera, o.width, o.height, o.supersample);
    renderer.setAmbient(o.ambient);
    const Image shown = o.ambient ? renderer.render(camera, o.width, o.height, o.supersample) : plain;
    const Image reference = converged.render(camera, o.width, o.height, o.supersample);
    r.solveMs = solveMs;
    r.shots = status.shots;
    r.importanceShots = solver.importanceShots();
    r.deliveryShots = solver.deliveryShots();
    r.convergence = status.convergence;
    const double seen = meanLuminance(reference);
    r.visibleConvergence = seen > 0 ? meanLuminance(plain) / seen : 1.0;
    r.imageError = imageError(plain, reference);
    r.shownError = imageError(shown, reference);
    r.imageRms = imageRmsError(plain, reference);
    r.shownRms = imageRmsError(shown, reference);
    if (!o.framesDir.empty()) {
      if (f == 0) scale = exposureScale(reference, o.exposure);  // one exposure: frames compare
      o.writeFrame(fmt::format("{}/frame_{:04d}.png", o.framesDir, f), shown, scale);
    }
    records.push_back(r);
    progress.frameDone(f);
  }
  return records;
}

void writeFramesCsv(const std::string& path, const std::vector<FrameRecord>& frames) {
  std::string out =
      "frame,time_s,solve_ms,shots,importance_shots,delivery_shots,convergence,visible_convergence,image_error,shown_"
      "error,image_rms,shown_rms\n";
  for (const FrameRecord& r : frames)
    out += fmt::format("{},{:.4f},{:.2f},{},{},{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", r.frame, r.time,
                       r.solveMs, r.shots, r.importanceShots, r.deliveryShots, r.convergence, r.visibleConvergence,
                       r.imageError, r.shownError, r.imageRms, r.shownRms);
  writeTextFile(path, out);
}

}  // namespace hemirad
